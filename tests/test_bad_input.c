/* The bad-input suite (docs/reliability.md): every case of tests/bad/ run
 * through a step binary, each with its exit status and its exact stderr,
 * and an existing output file that a failed run must leave byte for byte as
 * it was (no temporary file left either). Huge inputs are generated here.
 *   tests/bad/scenes/NAME.scene  a scene; NAME.err: "exit N", an optional
 *                                "args: ..." line, then the exact stderr
 *   tests/bad/cli.cases          "$ ARGS", "exit N", the exact stderr, then
 *                                a blank line; $OUT is the output file
 * docs/scene-format.md lists the errors; each message it shows for a file
 * NAME.scene must be the one this suite expects. */
#define _DEFAULT_SOURCE /* realpath */
#include "check.h"
#include "testfiles.h"
#include "bad_run.h"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define DOC "docs/reliability.md, \"The bad-input suite\""

#define SCENES "tests/bad/scenes"

/* Split an expectation: "exit N\n[args: ...\n]stderr..." */
static void parse_expect(char *text, int *status, const char **args, const char **err)
{
  cr_assert(sscanf(text, "exit %d", status) == 1, "an expectation must start with 'exit N'");
  char *rest = strchr(text, '\n');
  rest = rest ? rest + 1 : text + strlen(text);
  *args = "";
  if (strncmp(rest, "args: ", 6) == 0) {
    *args = rest + 6;
    rest = strchr(rest, '\n');
    cr_assert(rest);
    *rest++ = '\0';
  }
  *err = rest;
}

static int names_cmp(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* NAME of every NAME.scene in SCENES, sorted; their count in *n. */
static char **scene_names(int *n)
{
  DIR *d = opendir(SCENES);
  cr_assert(d, "no " SCENES);
  char **names = NULL;
  *n = 0;
  for (struct dirent *e; (e = readdir(d));) {
    size_t len = strlen(e->d_name);
    if (len > 6 && strcmp(e->d_name + len - 6, ".scene") == 0) {
      names = realloc(names, sizeof *names * (size_t)(*n + 1));
      names[(*n)++] = strndup(e->d_name, len - 6);
    }
  }
  closedir(d);
  qsort(names, (size_t)*n, sizeof *names, names_cmp);
  return names;
}

Test(bad_input, every_scene_case, .timeout = 900) /* hang guard; valgrind: ~150 s */
{
  mkdir(BUILD_DIR "/test-out", 0755);
  mkdir(WORK, 0755);
  Check c = CHECK(REL_STEP " --scene", DOC);
  int n;
  char **names = scene_names(&n);
  for (int k = 0; k < n; k++) {
    char path[PATH_MAX], args[PATH_MAX + 256];
    snprintf(path, sizeof path, SCENES "/%s.err", names[k]);
    long len;
    char *expect = testfiles_slurp(path, &len);
    CHECK_THAT(&c, expect != NULL, "%s.scene has no %s.err", names[k], names[k]);
    if (expect) {
      int status;
      const char *extra, *err;
      parse_expect(expect, &status, &extra, &err);
      snprintf(args, sizeof args, "--quiet --threads 1 --scene %s.scene -o $OUT %s",
               names[k], extra);
      check_case(&c, names[k], SCENES, args, status, err, 0);
      free(expect);
    }
    free(names[k]);
  }
  free(names);
  cr_expect(c.cases >= 100, "the suite holds %d scene cases, fewer than 100", c.cases / 3);
  CHECK_DONE(&c);
}

Test(bad_input, every_command_line_case, .timeout = 900)
{
  mkdir(BUILD_DIR "/test-out", 0755);
  mkdir(WORK, 0755);
  mkdir(WORK "/dir.png", 0755);
  Check c = CHECK(REL_STEP, DOC);
  long len;
  char *text = testfiles_slurp("tests/bad/cli.cases", &len);
  cr_assert(text, "no tests/bad/cli.cases");
  int cases = 0;
  for (char *rec = text; *rec;) {
    char *end = strstr(rec, "\n\n"); /* a record ends with one '\n' */
    if (end)
      *++end = '\0';
    end = end ? end + 1 : rec + strlen(rec);
    if (strncmp(rec, "$ ", 2) == 0) {
      char *args = rec + 2, *nl = strchr(args, '\n');
      cr_assert(nl, "a case without status: %s", rec);
      *nl = '\0';
      int status;
      const char *extra, *err;
      parse_expect(nl + 1, &status, &extra, &err);
      check_case(&c, args, ".", args, status, err, 0);
      cases++;
    }
    rec = end;
  }
  free(text);
  cr_expect(cases >= 40, "the suite holds %d command-line cases, fewer than 40", cases);
  CHECK_DONE(&c);
}

/* Each "NAME.scene:L:C: message" line of docs/scene-format.md must be the
 * suite's expected stderr for tests/bad/scenes/NAME.scene. */
Test(bad_input, the_documented_messages_are_the_real_ones)
{
  long len;
  char *doc = testfiles_slurp("docs/scene-format.md", &len);
  cr_assert(doc, "no docs/scene-format.md");
  Check c = CHECK("docs/scene-format.md", "docs/scene-format.md, \"Errors\"");
  int found = 0;
  for (char *line = strtok(doc, "\n"); line; line = strtok(NULL, "\n")) {
    char name[128];
    int n = 0;
    if (sscanf(line, "%127[a-z0-9_-].scene:%*d:%*d: %n", name, &n) < 1 || n == 0)
      continue;
    char path[256];
    snprintf(path, sizeof path, SCENES "/%s.err", name);
    long elen;
    char *expect = testfiles_slurp(path, &elen);
    found++;
    CHECK_THAT(&c, expect && strstr(expect, line) != NULL, "the doc shows\n    %s\n  but "
               "%s holds\n%s", line, path, expect ? expect : "(no such file)\n");
    free(expect);
  }
  cr_expect(found >= 30, "docs/scene-format.md shows %d error messages of the suite", found);
  free(doc);
  CHECK_DONE(&c);
}
