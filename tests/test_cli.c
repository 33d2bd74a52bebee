/* Tests of the step binaries' command line (step 03 on, through the step's
 * own binary): --help, bad usage, a bad scene never overwrites the output,
 * and the thread count never changes the bytes. README.md. */
#include <criterion/criterion.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#define BIN BUILD_DIR "/bin/" STEP_NAME
#define OUT BUILD_DIR "/test-out/cli-"

/* Exit status of a shell command, -1 when it did not exit normally. */
static int run(const char *cmd)
{
  int status = system(cmd);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The whole file into a new buffer; its length in *n. NULL when unreadable. */
static char *slurp(const char *path, long *n)
{
  FILE *f = fopen(path, "rb");
  if (!f)
    return NULL;
  fseek(f, 0, SEEK_END);
  *n = ftell(f);
  rewind(f);
  char *buf = malloc((size_t)*n + 1);
  if (buf && fread(buf, 1, (size_t)*n, f) != (size_t)*n) {
    free(buf);
    buf = NULL;
  }
  if (buf)
    buf[*n] = '\0';
  fclose(f);
  return buf;
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
  int tried = 0;
  for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
    char bin[256], cmd[512];
    snprintf(bin, sizeof bin, "%s/bin/%s", BUILD_DIR, steps[k]);
    struct stat st;
    if (stat(bin, &st) != 0)
      continue;
    tried++;
    snprintf(cmd, sizeof cmd, "%s --help > /dev/null", bin);
    cr_expect(run(cmd) == 0, "%s --help did not exit 0", steps[k]);
  }
  cr_expect(tried > 0 && run(BIN " --help | grep -q -- --threads") == 0,
            "--help of " STEP_NAME " does not list --threads");
}

Test(cli, bad_usage_exits_2)
{
  const char *bad[] = {"--bogus", "--width 0", "--width 99999", "--threads x",
                       "--tonemap aces", "extra-argument", "--width"};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    char cmd[256];
    snprintf(cmd, sizeof cmd, "%s %s -o %snever.png 2> /dev/null", BIN, bad[k], OUT);
    cr_expect(run(cmd) == 2, "'%s' did not exit 2", bad[k]);
  }
  struct stat st;
  cr_expect(stat(OUT "never.png", &st) != 0, "bad usage wrote an image");
}

Test(cli, bad_scene_reports_file_line_col_and_keeps_the_output)
{
  mkdir(BUILD_DIR "/test-out", 0755);
  const char *scene = OUT "bad.scene", *out = OUT "keep.png", *err = OUT "bad.err";
  write_file(scene, "material red diffuse 1 0 0\n"
                    "sphere center 0 1 0 radius -1 material red\n");
  const char old[] = "an existing output, not a PNG\n";
  write_file(out, old);
  int rc = run(BIN " --quiet --scene " OUT "bad.scene -o " OUT "keep.png 2> " OUT "bad.err");
  cr_expect(rc == 1, "exit status %d, expected 1", rc);
  long n;
  char *msg = slurp(err, &n);
  cr_assert(msg);
  /* Line 2, column 28: the value after 'radius'. */
  const char *want = OUT "bad.scene:2:28: expected a radius > 0, found '-1'\n";
  cr_expect(strcmp(msg, want) == 0, "stderr:\n%s\nexpected:\n%s", msg, want);
  free(msg);
  char *now = slurp(out, &n);
  cr_assert(now);
  cr_expect(n == (long)sizeof old - 1 && memcmp(now, old, sizeof old - 1) == 0,
            "the existing output was changed");
  free(now);
  (void)scene;
}

Test(cli, thread_count_does_not_change_the_bytes, .timeout = 120)
{
  mkdir(BUILD_DIR "/test-out", 0755);
  cr_assert(run(BIN " --quiet --width 161 --height 97 --threads 1 -o " OUT "t1.png") == 0);
  cr_assert(run(BIN " --quiet --width 161 --height 97 --threads 2 -o " OUT "t2.png") == 0);
  cr_assert(run(BIN " --quiet --width 161 --height 97 --threads 2 -o " OUT "t2.pfm") == 0);
  cr_assert(run(BIN " --quiet --width 161 --height 97 --threads 3 -o " OUT "t3.pfm") == 0);
  long n1, n2, n3, n4;
  char *a = slurp(OUT "t1.png", &n1), *b = slurp(OUT "t2.png", &n2);
  char *c = slurp(OUT "t2.pfm", &n3), *d = slurp(OUT "t3.pfm", &n4);
  cr_assert(a && b && c && d);
  cr_expect(n1 == n2 && memcmp(a, b, (size_t)n1) == 0, "PNG differs between 1 and 2 threads");
  cr_expect(n3 == n4 && memcmp(c, d, (size_t)n3) == 0, "PFM differs between 2 and 3 threads");
  free(a);
  free(b);
  free(c);
  free(d);
}
