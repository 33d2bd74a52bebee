/* Tests of output files (step 01): the mode of a new file follows the umask,
 * a replaced file keeps its mode, a signal that ends the program during the
 * write leaves neither a temporary file nor a changed output, and a failed
 * PNG write says one line of its own. docs/reliability.md, "Output files". */
#include "check.h"
#include "testfiles.h"

#include <dirent.h>
#include "threads.h"
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/image.h"
#include "app/outfile.h"

#define DOC "docs/reliability.md, \"Output files\""
#define DIR_ BUILD_DIR "/test-out/outfile"

static const char OLD[] = "the previous picture, not to be lost\n";

static void put(const char *path, const char *text, mode_t mode)
{
  mkdir(BUILD_DIR "/test-out", 0755);
  mkdir(DIR_, 0755);
  FILE *f = fopen(path, "wb");
  cr_assert(f && fputs(text, f) >= 0 && fclose(f) == 0, "cannot write %s", path);
  cr_assert(chmod(path, mode) == 0);
}

static bool holds(const char *path, const char *text)
{
  char buf[256] = "";
  FILE *f = fopen(path, "rb");
  size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
  if (f)
    fclose(f);
  return n == strlen(text) && memcmp(buf, text, n) == 0;
}

static mode_t mode_of(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0 ? st.st_mode & 07777 : (mode_t)-1;
}

Test(outfile, a_new_file_gets_0666_less_the_umask)
{
  static const mode_t masks[] = {022, 027, 077, 0};
  Check c = CHECK("image_save", DOC);
  float rgb[3] = {0.5f, 0.5f, 0.5f};
  for (size_t k = 0; k < sizeof masks / sizeof masks[0]; k++) {
    put(DIR_ "/new.pfm", "", 0644);
    remove(DIR_ "/new.pfm");
    umask(masks[k]);
    cr_assert(image_save(DIR_ "/new.pfm", 1, 1, rgb, TONEMAP_CLAMP));
    CHECK_INT(&c, 0666 & ~masks[k], mode_of(DIR_ "/new.pfm"), "mode of a new file under "
              "umask 0%03o (as decimal numbers)", (unsigned)masks[k]);
  }
}

Test(outfile, a_replaced_file_keeps_its_mode)
{
  static const mode_t modes[] = {0600, 0640, 0604, 0755};
  Check c = CHECK("image_save", DOC);
  float rgb[3] = {0.5f, 0.5f, 0.5f};
  umask(077);
  for (size_t k = 0; k < sizeof modes / sizeof modes[0]; k++) {
    put(DIR_ "/old.png", OLD, modes[k]);
    cr_assert(image_save(DIR_ "/old.png", 1, 1, rgb, TONEMAP_CLAMP));
    CHECK_INT(&c, modes[k], mode_of(DIR_ "/old.png"), "mode of a replaced file that had "
              "mode 0%03o, umask 077 (as decimal numbers)", (unsigned)modes[k]);
    CHECK_THAT(&c, !holds(DIR_ "/old.png", OLD), "the file was not replaced");
  }
}

/* In a child: open the output, write part of it, raise `sig`. The child must
 * die of it, leave no temporary file and the old contents. */
static void killed_while_writing(Check *c, int sig, const char *name)
{
  put(DIR_ "/sig.pfm", OLD, 0644);
  fflush(NULL);
  pid_t pid = fork();
  cr_assert(pid >= 0);
  if (pid == 0) {
    /* The default action, as a program started from a terminal has it: a
     * test run in the background of a script starts with SIGINT ignored,
     * which outfile_open rightly leaves ignored. */
    signal(sig, SIG_DFL);
    OutFile out;
    if (!outfile_open(&out, DIR_ "/sig.pfm"))
      _exit(3);
    fputs("PF\n1 1\n-1.0\n", out.f);
    fflush(out.f);
    raise(sig);
    _exit(4); /* the signal did not end the program */
  }
  int status;
  waitpid(pid, &status, 0);
  CHECK_THAT(c, WIFSIGNALED(status) && WTERMSIG(status) == sig, "%s while writing: the "
             "program must die of it (status 0x%x)", name, (unsigned)status);
  CHECK_INT(c, 0, testfiles_count(DIR_, "sig.pfm.tmp"), "%s while writing: temporary files left", name);
  CHECK_THAT(c, holds(DIR_ "/sig.pfm", OLD), "%s while writing: the old file was changed",
             name);
}

Test(outfile, a_signal_during_the_write_leaves_no_temporary_file)
{
  Check c = CHECK("outfile_open", DOC);
  killed_while_writing(&c, SIGINT, "SIGINT");
  killed_while_writing(&c, SIGTERM, "SIGTERM");
  killed_while_writing(&c, SIGHUP, "SIGHUP");
  CHECK_DONE(&c);
}

Test(outfile, ignored_signals_stay_ignored_and_handlers_come_back)
{
  Check c = CHECK("outfile_close", DOC);
  put(DIR_ "/ign.pfm", OLD, 0644);
  signal(SIGINT, SIG_DFL); /* as from a terminal (see killed_while_writing) */
  signal(SIGHUP, SIG_IGN);
  OutFile out;
  cr_assert(outfile_open(&out, DIR_ "/ign.pfm"));
  fputs("new\n", out.f);
  raise(SIGHUP); /* nohup's case: ignored, the write goes on */
  cr_assert(outfile_close(&out, true));
  CHECK_THAT(&c, holds(DIR_ "/ign.pfm", "new\n"), "the file was not written");
  struct sigaction sa;
  sigaction(SIGINT, NULL, &sa);
  CHECK_THAT(&c, sa.sa_handler == SIG_DFL, "after outfile_close, SIGINT must have its "
             "default action again");
  sigaction(SIGHUP, NULL, &sa);
  CHECK_THAT(&c, sa.sa_handler == SIG_IGN, "after outfile_close, SIGHUP must be ignored "
             "again");
}

/* Noise (an LCG) that PNG cannot compress below 1000 bytes. Its bytes come
 * from film_to_byte, which a starter's step 01 stubs to 0 for every
 * channel: the picture is BIG x BIG so that even a constant one stays over
 * 1000 bytes (deflate shrinks a run at most about 1000 times; 3 MiB of bytes). */
enum { BIG = 1024 };
static float *noise(int n)
{
  float *rgb = malloc((size_t)n * 3 * sizeof *rgb);
  uint32_t x = 12345;
  for (int k = 0; rgb && k < n * 3; k++) {
    x = x * 1664525u + 1013904223u;
    rgb[k] = (float)(x >> 24) / 255.0f;
  }
  return rgb;
}

Test(outfile, a_file_size_limit_ends_the_program_without_a_trace)
{
  /* RLIMIT_FSIZE with SIGXFSZ's default action: the write kills the program. */
  Check c = CHECK("outfile_open", DOC);
  put(DIR_ "/big.png", OLD, 0644);
  float *rgb = noise(BIG * BIG);
  fflush(NULL);
  pid_t pid = fork();
  cr_assert(pid >= 0);
  if (pid == 0) {
    (void)omp_get_max_threads(); /* as below: the runtime started before the limit */
    struct rlimit lim = {1000, 1000};
    setrlimit(RLIMIT_FSIZE, &lim);
    image_save(DIR_ "/big.png", BIG, BIG, rgb, TONEMAP_CLAMP);
    _exit(4);
  }
  int status;
  waitpid(pid, &status, 0);
  CHECK_THAT(&c, WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ, "over the file size "
             "limit: the program must die of SIGXFSZ (status 0x%x)", (unsigned)status);
  CHECK_INT(&c, 0, testfiles_count(DIR_, "big.png.tmp"), "over the file size limit: temporary files left");
  CHECK_THAT(&c, holds(DIR_ "/big.png", OLD), "over the file size limit: the old file changed");
  free(rgb);
}

Test(outfile, a_failed_png_write_says_one_line_of_its_own)
{
  /* SIGXFSZ ignored: the write fails with EFBIG inside libpng. */
  put(DIR_ "/fail.png", OLD, 0644);
  float *rgb = noise(BIG * BIG);
  /* Start the OpenMP runtime first, as a render does (the PNG's bands go to
   * threads): LLVM's writes a shared-memory file when it starts, which the
   * limit refuses, and then stops (make sanitize-clang). */
  (void)omp_get_max_threads();
  signal(SIGXFSZ, SIG_IGN);
  struct rlimit lim = {1000, 1000};
  cr_assert(setrlimit(RLIMIT_FSIZE, &lim) == 0);
  fflush(stderr);
  FILE *tmp = tmpfile();
  int saved = dup(2);
  dup2(fileno(tmp), 2);
  bool ok = image_save(DIR_ "/fail.png", BIG, BIG, rgb, TONEMAP_CLAMP);
  fflush(stderr);
  dup2(saved, 2);
  close(saved);
  char buf[512] = "";
  rewind(tmp);
  buf[fread(buf, 1, sizeof buf - 1, tmp)] = '\0';
  fclose(tmp);
  Check c = CHECK("image_save", DOC);
  CHECK_THAT(&c, !ok, "a PNG over the file size limit was saved");
  const char *want = "image: cannot write '" DIR_ "/fail.png': File too large\n";
  CHECK_THAT(&c, strcmp(buf, want) == 0, "stderr of a failed PNG write\n  expected %s  got "
             "     %s", want, buf);
  CHECK_THAT(&c, holds(DIR_ "/fail.png", OLD), "the old file was changed");
  free(rgb);
}
