/* Tests of the step binaries' command line (step 03 on, through the step's
 * own binary): --help, bad usage, a bad scene never overwrites the output,
 * and the thread count never changes the bytes. README.md, "Running a step";
 * every bad command line of tests/bad/cli.cases runs in the bad-input suite. */
#include "check.h"
#include "testfiles.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#define BIN BUILD_DIR "/bin/" STEP_NAME
#define OUT BUILD_DIR "/test-out/cli-"
#define DOC "README.md, \"Running a step\""

/* Exit status of a shell command, -1 when it did not exit normally. */
static int run(const char *cmd)
{
  int status = system(cmd);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void write_file(const char *path, const char *text)
{
  FILE *f = fopen(path, "wb");
  cr_assert(f, "cannot write %s", path);
  fputs(text, f);
  fclose(f);
}

Test(cli, help_exits_0_for_every_step_present)
{
  static const char *const steps[] = {"01-film", "02-intersection", "03-camera", "04-phong",
                                      "05-shadows", "06-ambient", "07-antialiasing",
                                      "08-area-lights"};
  Check c = CHECK("app_run", DOC);
  int tried = 0;
  for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
    char bin[256], cmd[512];
    snprintf(bin, sizeof bin, "%s/bin/%s", BUILD_DIR, steps[k]);
    struct stat st;
    if (stat(bin, &st) != 0)
      continue;
    tried++;
    snprintf(cmd, sizeof cmd, "%s --help > /dev/null", bin);
    CHECK_INT(&c, 0, run(cmd), "%s --help: exit status", steps[k]);
  }
  CHECK_THAT(&c, tried > 0, "no step binary found in " BUILD_DIR "/bin");
  CHECK_INT(&c, 0, run(BIN " --help | grep -q -- --threads"),
            STEP_NAME " --help lists --threads (grep's exit status)");
}

Test(cli, bad_usage_exits_2)
{
  static const char *const bad[] = {"--bogus", "--width 0", "--width 99999", "--threads x",
                                    "--tonemap aces", "extra-argument", "--width"};
  Check c = CHECK("cli_parse", DOC);
  mkdir(BUILD_DIR "/test-out", 0755);
  remove(OUT "never.png");
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    char cmd[256];
    snprintf(cmd, sizeof cmd, "%s %s -o %snever.png 2> /dev/null", BIN, bad[k], OUT);
    CHECK_INT(&c, 2, run(cmd), STEP_NAME " %s: exit status (2: bad usage)", bad[k]);
  }
  struct stat st;
  CHECK_THAT(&c, stat(OUT "never.png", &st) != 0, "bad usage wrote an image");
  CHECK_DONE(&c);
}

Test(cli, bad_scene_reports_file_line_col_and_keeps_the_output)
{
  mkdir(BUILD_DIR "/test-out", 0755);
  write_file(OUT "bad.scene", "material red diffuse 1 0 0\n"
                              "sphere center 0 1 0 radius -1 material red\n");
  const char old[] = "an existing output, not a PNG\n";
  write_file(OUT "keep.png", old);
  Check c = CHECK("app_run", DOC);
  int rc = run(BIN " --quiet --scene " OUT "bad.scene -o " OUT "keep.png 2> " OUT "bad.err");
  CHECK_INT(&c, 1, rc, "a scene with radius -1: exit status (1: bad scene)");
  long n = 0;
  char *msg = testfiles_slurp(OUT "bad.err", &n);
  cr_assert(msg, "no stderr file " OUT "bad.err");
  /* Line 2, column 28: the value after 'radius'. */
  const char *want = OUT "bad.scene:2:28: expected a radius > 0, found '-1'\n";
  CHECK_THAT(&c, strcmp(msg, want) == 0, "a scene with radius -1 on line 2\n  expected "
             "stderr %s  got stderr      %s", want, msg);
  free(msg);
  char *now = testfiles_slurp(OUT "keep.png", &n);
  cr_assert(now, "the existing output " OUT "keep.png is gone");
  CHECK_THAT(&c, n == (long)sizeof old - 1 && memcmp(now, old, sizeof old - 1) == 0,
             "after the failed run, the existing output was changed");
  free(now);
}

Test(cli, thread_count_does_not_change_the_bytes, .timeout = 120)
{
  mkdir(BUILD_DIR "/test-out", 0755);
  Check c = CHECK("render", "docs/01-film.md, \"The math\"");
  static const char *const runs[][2] = {{"1", "t1.png"}, {"2", "t2.png"}, {"2", "t2.pfm"},
                                        {"3", "t3.pfm"}};
  for (int k = 0; k < 4; k++) {
    char cmd[512];
    /* stderr kept aside: step 03 says it ignores its default scene's lights. */
    snprintf(cmd, sizeof cmd, "%s --quiet --width 161 --height 97 --threads %s -o %s%s 2>%st.err",
             BIN, runs[k][0], OUT, runs[k][1], OUT);
    CHECK_INT(&c, 0, run(cmd), "161 x 97 with %s threads to %s: exit status", runs[k][0],
              runs[k][1]);
  }
  long n1 = 0, n2 = 0, n3 = 0, n4 = 0;
  char *a = testfiles_slurp(OUT "t1.png", &n1), *b = testfiles_slurp(OUT "t2.png", &n2);
  char *p = testfiles_slurp(OUT "t2.pfm", &n3), *q = testfiles_slurp(OUT "t3.pfm", &n4);
  cr_assert(a && b && p && q, "a render of the test wrote no file");
  CHECK_THAT(&c, n1 == n2 && memcmp(a, b, (size_t)n1) == 0,
             "the PNG differs between 1 and 2 threads (%ld and %ld bytes)", n1, n2);
  CHECK_THAT(&c, n3 == n4 && memcmp(p, q, (size_t)n3) == 0,
             "the PFM differs between 2 and 3 threads (%ld and %ld bytes)", n3, n4);
  free(a);
  free(b);
  free(p);
  free(q);
}
