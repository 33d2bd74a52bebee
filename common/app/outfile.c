/* Output files replaced atomically (step 01): a temporary file beside the
 * final name, renamed when complete, removed on failure or on a signal that
 * ends the program. docs/reliability.md, "Output files". */
#include "app/outfile.h"

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* What the signal handler removes. Globals, because a handler sees nothing
 * else; only one output file is open at a time. */
static char *volatile tmp_name;
static volatile sig_atomic_t tmp_live;

static const int SIGNALS[] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};
enum { N_SIGNALS = sizeof SIGNALS / sizeof SIGNALS[0] };
static struct sigaction saved[N_SIGNALS];

/* Remove the temporary file, then die of the signal as if not caught (it
 * stays blocked until the handler returns). unlink, signal and raise are
 * async-signal-safe. */
static void on_signal(int sig)
{
  if (tmp_live)
    unlink(tmp_name);
  signal(sig, SIG_DFL);
  raise(sig);
}

/* Catch the signals that end the program, except those it ignores (nohup). */
static void watch(void)
{
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  for (int k = 0; k < N_SIGNALS; k++) {
    sigaction(SIGNALS[k], NULL, &saved[k]);
    if (saved[k].sa_handler != SIG_IGN)
      sigaction(SIGNALS[k], &sa, NULL);
  }
}

static void unwatch(void)
{
  for (int k = 0; k < N_SIGNALS; k++)
    sigaction(SIGNALS[k], &saved[k], NULL);
}

/* The mode the new file gets: the replaced file's, or 0666 less the umask. */
static mode_t new_mode(const char *path)
{
  struct stat st;
  if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
    return st.st_mode & 07777;
  mode_t mask = umask(0);
  umask(mask);
  return 0666 & ~mask;
}

static bool fail(const char *path, int err)
{
  fprintf(stderr, "image: cannot write '%s': %s\n", path, strerror(err));
  return false;
}

bool outfile_open(OutFile *out, const char *path)
{
  *out = (OutFile){.f = NULL, .path = path, .failed = false, .err = 0};
  size_t size = strlen(path) + 16;
  char *tmp = malloc(size);
  if (!tmp)
    return fail(path, ENOMEM);
  snprintf(tmp, size, "%s.tmp.XXXXXX", path);
  sigset_t block, old;
  sigemptyset(&block);
  for (int k = 0; k < N_SIGNALS; k++)
    sigaddset(&block, SIGNALS[k]);
  sigprocmask(SIG_BLOCK, &block, &old); /* no signal between create and record */
  watch();
  int fd = mkstemp(tmp);
  int err = errno;
  if (fd >= 0) {
    tmp_name = tmp;
    tmp_live = 1;
  }
  sigprocmask(SIG_SETMASK, &old, NULL);
  if (fd < 0) {
    unwatch();
    free(tmp);
    return fail(path, err);
  }
  if (fchmod(fd, new_mode(path)) == 0 && (out->f = fdopen(fd, "wb")))
    return true;
  out->err = errno;
  close(fd);
  return outfile_close(out, false);
}

bool outfile_close(OutFile *out, bool ok)
{
  int err = out->err ? out->err : EIO;
  ok = ok && !out->failed;
  if (out->f && fclose(out->f) != 0 && ok) {
    ok = false;
    err = errno;
  }
  if (ok && rename(tmp_name, out->path) != 0) {
    ok = false;
    err = errno;
  }
  if (!ok)
    unlink(tmp_name);
  tmp_live = 0;
  unwatch();
  free(tmp_name);
  tmp_name = NULL;
  out->f = NULL;
  return ok || fail(out->path, err);
}
