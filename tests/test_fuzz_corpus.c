/* The fuzzing regression corpus (docs/reliability.md, "Fuzzing"): every
 * input that ever crashed a target, in tests/fuzz/regressions/TARGET/, fed
 * again to the same entry points in this plain build (and under make
 * sanitize's). A target aborts on a bug, so a regression shows as a crash;
 * the messages of the inputs go to BUILD_DIR/test-out/fuzz-replay.log, each
 * after a line naming its file. */
#define _DEFAULT_SOURCE /* DT_REG */
#include "check.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fuzz/fuzz.h"

#define DOC "docs/reliability.md, \"Fuzzing\""
#define REGRESSIONS "tests/fuzz/regressions"
#define LOG BUILD_DIR "/test-out/fuzz-replay.log"

/* Feed each file of REGRESSIONS/target to `entry`; returns how many. */
static int replay(const char *target, void (*entry)(const uint8_t *, size_t))
{
  char dir[256];
  snprintf(dir, sizeof dir, REGRESSIONS "/%s", target);
  DIR *d = opendir(dir);
  if (!d)
    return 0;
  mkdir(BUILD_DIR "/test-out", 0755);
  fflush(NULL);
  int log = open(LOG, O_WRONLY | O_CREAT | O_APPEND, 0644), out = dup(1), err = dup(2);
  cr_assert(log >= 0 && out >= 0 && err >= 0, "cannot open " LOG);
  dup2(log, 1);
  dup2(log, 2);
  int n = 0;
  for (struct dirent *e; (e = readdir(d));) {
    if (e->d_name[0] == '.')
      continue;
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    FILE *f = fopen(path, "rb");
    if (!f)
      continue;
    uint8_t *buf = malloc(1 << 20);
    size_t size = buf ? fread(buf, 1, 1 << 20, f) : 0;
    fclose(f);
    fprintf(stderr, "== %s\n", path);
    fflush(stderr);
    entry(buf, size);
    fflush(NULL);
    free(buf);
    n++;
  }
  closedir(d);
  dup2(out, 1);
  dup2(err, 2);
  close(out);
  close(err);
  close(log);
  return n;
}

Test(fuzz_corpus, every_input_that_ever_crashed_runs_clean, .timeout = 120)
{
  Check c = CHECK("fuzz_scene, fuzz_cli, fuzz_render", DOC);
  int n = replay("scene", fuzz_scene) + replay("cli", fuzz_cli) + replay("render", fuzz_render);
  /* Each scene input through the render target too, and back. */
  n += replay("scene", fuzz_render) + replay("render", fuzz_scene);
  CHECK_THAT(&c, n > 0, "no input found in " REGRESSIONS "/scene, cli or render");
}
