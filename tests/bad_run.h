/* The bad-input suite's runner (docs/reliability.md, "The bad-input suite"):
 * a step binary run on a case with an existing output file, its exit status
 * and exact stderr compared, the output file and its folder checked after a
 * failure. Shared by tests/test_bad_input.c and tests/test_huge_input.c. */
#ifndef RT_BAD_RUN_H
#define RT_BAD_RUN_H

#include "check.h"
#include "testfiles.h"

#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define WORK BUILD_DIR "/test-out/bad"
#define OLD "an existing output, not a picture\n"

static inline void write_text(const char *path, const char *text)
{
  FILE *f = fopen(path, "wb");
  cr_assert(f && fputs(text, f) >= 0 && fclose(f) == 0, "cannot write %s", path);
}

/* `text` with every $OUT replaced by `out` and $WORK by WORK's absolute
 * path, in a new buffer. */
static inline char *expand(const char *text, const char *out)
{
  char work[PATH_MAX];
  cr_assert(realpath(WORK, work));
  size_t n = strlen(text) + 1, k = 0;
  for (const char *p = strchr(text, '$'); p; p = strchr(p + 1, '$'))
    n += strlen(out) + strlen(work);
  char *buf = malloc(n);
  cr_assert(buf);
  for (const char *p = text; *p;) {
    if (strncmp(p, "$OUT", 4) == 0) {
      k += (size_t)sprintf(buf + k, "%s", out);
      p += 4;
    } else if (strncmp(p, "$WORK", 5) == 0) {
      k += (size_t)sprintf(buf + k, "%s", work);
      p += 5;
    } else {
      buf[k++] = *p++;
    }
  }
  buf[k] = '\0';
  return buf;
}

typedef struct Run {
  int status; /* exit status, or 128 + signal */
  char *err;  /* what it wrote on stderr (caller frees) */
} Run;

/* Run the step binary with `args` (split at spaces; '' is an empty word) in
 * directory `dir`, stdin and stdout on /dev/null, under `limit_as` bytes of
 * address space when not 0. */
static inline Run run(const char *dir, const char *args, rlim_t limit_as)
{
  char bin[PATH_MAX], *words = strdup(args), *argv[256];
  cr_assert(realpath(BUILD_DIR "/bin/" REL_STEP, bin), "no " BUILD_DIR "/bin/" REL_STEP);
  int argc = 0;
  argv[argc++] = bin;
  for (char *w = strtok(words, " "); w && argc < 255; w = strtok(NULL, " "))
    argv[argc++] = strcmp(w, "''") == 0 ? (char *)"" : w;
  argv[argc] = NULL;
  FILE *err = tmpfile();
  cr_assert(err);
  fflush(NULL);
  pid_t pid = fork();
  cr_assert(pid >= 0);
  if (pid == 0) {
    int null = open("/dev/null", O_RDWR);
    dup2(null, 0);
    dup2(null, 1);
    dup2(fileno(err), 2);
    struct rlimit lim = {limit_as, limit_as};
    if ((limit_as && setrlimit(RLIMIT_AS, &lim) != 0) || chdir(dir) != 0)
      _exit(125);
    execv(bin, argv);
    _exit(126);
  }
  int st;
  waitpid(pid, &st, 0);
  free(words);
  Run r = {WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st), NULL};
  long n = ftell(err);
  r.err = calloc((size_t)n + 1, 1);
  rewind(err);
  cr_assert(r.err && fread(r.err, 1, (size_t)n, err) == (size_t)n);
  fclose(err);
  return r;
}

/* One case: run, compare status and stderr, and after a failure the output
 * file and the folder it is in. */
static inline void check_case(Check *c, const char *name, const char *dir, const char *args,
                       int want_status, const char *want_err, rlim_t limit_as)
{
  char out[PATH_MAX], base[64], tmp[80];
  cr_assert(realpath(WORK, out));
  snprintf(base, sizeof base, "out-%ld.png", (long)getpid()); /* tests run in parallel */
  snprintf(tmp, sizeof tmp, "%s.tmp", base);
  strcat(out, "/");
  strcat(out, base);
  write_text(out, OLD);
  char *a = expand(args, out), *w = expand(want_err, out);
  Run r = run(dir, a, limit_as);
  CHECK_THAT(c, r.status == want_status && strcmp(r.err, w) == 0,
             "%s: %s\n  expected exit %d, stderr\n%s  got exit %d, stderr\n%s", name, a,
             want_status, w, r.status, r.err);
  if (want_status != 0) {
    long n;
    char *now = testfiles_slurp(out, &n);
    CHECK_THAT(c, now && strcmp(now, OLD) == 0, "%s: the existing output file was changed",
               name);
    CHECK_INT(c, 0, testfiles_count(WORK, tmp), "%s: temporary files left", name);
    free(now);
  }
  free(a);
  free(w);
  free(r.err);
}

#endif
