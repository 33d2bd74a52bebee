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

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define DOC "docs/reliability.md, \"The bad-input suite\""

/* AddressSanitizer reserves terabytes of address space: no RLIMIT_AS then. */
#if defined(__SANITIZE_ADDRESS__)
#define REL_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define REL_ASAN 1
#endif
#endif
#ifndef REL_ASAN
#define REL_ASAN 0
#endif
#define SCENES "tests/bad/scenes"
#define WORK BUILD_DIR "/test-out/bad"
#define OLD "an existing output, not a picture\n"

static void write_text(const char *path, const char *text)
{
  FILE *f = fopen(path, "wb");
  cr_assert(f && fputs(text, f) >= 0 && fclose(f) == 0, "cannot write %s", path);
}

/* `text` with every $OUT replaced by `out` and $WORK by WORK's absolute
 * path, in a new buffer. */
static char *expand(const char *text, const char *out)
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
static Run run(const char *dir, const char *args, rlim_t limit_as)
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
static void check_case(Check *c, const char *name, const char *dir, const char *args,
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

/* Write `head`, then `n` copies of `fill`, then `tail` to WORK/name. */
static void generate(const char *name, const char *head, const char *fill, long n,
                     const char *tail)
{
  char path[PATH_MAX];
  snprintf(path, sizeof path, WORK "/%s", name);
  FILE *f = fopen(path, "wb");
  cr_assert(f);
  fputs(head, f);
  for (long k = 0; k < n; k++)
    fputs(fill, f);
  fputs(tail, f);
  cr_assert(fclose(f) == 0);
}

#define STATEMENTS "(film, camera, ambient, background, material, plane, sphere, " \
                   "light, samples, light_samples)"

Test(bad_input, huge_generated_inputs, .timeout = 900)
{
  mkdir(BUILD_DIR "/test-out", 0755);
  mkdir(WORK, 0755);
  Check c = CHECK(REL_STEP " --scene", DOC);
  const char *args = "--quiet --threads 1 -o $OUT --scene ";
  char cmd[256];
  /* 10^6 lines: the line number of the last one. */
  generate("lines.scene", "film 8 6\n", "# a comment\n", 999998, "teapot 1\n");
  snprintf(cmd, sizeof cmd, "%slines.scene", args);
  check_case(&c, "10^6 lines", WORK, cmd, 1, "lines.scene:1000000:1: expected a statement "
             STATEMENTS ", found 'teapot'\n", 0);
  /* A 10 MB comment is only a comment. */
  generate("comment.scene", "film 8 6 #", "0123456789", 1000000, "\n");
  snprintf(cmd, sizeof cmd, "%scomment.scene", args);
  check_case(&c, "a 10 MB comment", WORK, cmd, 0, "", 0);
  /* A 10 MB word, and a word after 10 MB of spaces: columns past 10^7. */
  generate("word.scene", "film 8 6 ", "0123456789", 1000000, "\n");
  snprintf(cmd, sizeof cmd, "%sword.scene", args);
  check_case(&c, "a 10 MB word", WORK, cmd, 1, "word.scene:1:10: expected a word of at "
             "most 63 characters, found a longer one\n", 0);
  generate("spaces.scene", "", "          ", 1000000, "teapot\n");
  snprintf(cmd, sizeof cmd, "%sspaces.scene", args);
  check_case(&c, "a word after 10 MB of spaces", WORK, cmd, 1, "spaces.scene:1:10000001: "
             "expected a statement " STATEMENTS ", found 'teapot'\n", 0);
  /* 5 x 10^5 words on one line: the 65th, the 64th '1', is refused at column
   * 4 + 2 * 64. */
  generate("words.scene", "film", " 1", 500000, "\n");
  snprintf(cmd, sizeof cmd, "%swords.scene", args);
  check_case(&c, "5 x 10^5 words on a line", WORK, cmd, 1, "words.scene:1:132: expected "
             "at most 64 words on a line, found more\n", 0);
  CHECK_DONE(&c);
}

Test(bad_input, many_materials_in_constant_time_each, .timeout = 120)
{
  /* 2 x 10^5 materials, each used by one sphere (a linear lookup took 140 s;
   * the timeout guards against a quadratic one coming back). */
  mkdir(BUILD_DIR "/test-out", 0755);
  mkdir(WORK, 0755);
  char path[] = WORK "/materials.scene";
  FILE *f = fopen(path, "wb");
  cr_assert(f);
  fputs("film 8 6\ncamera eye 0 0 30 center 0 0 0\n", f);
  for (int k = 0; k < 200000; k++)
    fprintf(f, "material m%d diffuse 0.5 0.5 0.5\n", k);
  for (int k = 0; k < 200000; k++)
    fprintf(f, "sphere center %d %d -5 radius 0.1 material m%d\n", k % 400 - 200,
            k / 400 - 250, 199999 - k);
  fputs("sphere center 0 0 0 radius 1 material m200000\n", f);
  cr_assert(fclose(f) == 0);
  Check c = CHECK(REL_STEP " --scene", DOC);
  check_case(&c, "2 x 10^5 materials and a sphere naming an undefined one", WORK,
             "--quiet --threads 1 -o $OUT --scene materials.scene", 1,
             "materials.scene:400003:39: expected a defined material name (m0, m1, m2, m3, "
             "m4, m5, m6, m7, m8, m9, m10, m11, m12, m13, m14, m15, m16, m17, m18, m19, m20, "
             "m21, m22, m23, m24, m25, m26, m27, m28, m29, m30, m31, m32, m33, m34, m35, m36, "
             "m37, m38, m39, m40, m41, m42, m43, m44, m45, m46, m47, m48, m49, m50, m51, ...), "
             "found 'm200000'\n", 0);
  CHECK_DONE(&c);
}

Test(bad_input, files_too_large_to_read)
{
  /* A sparse file past the 2 GiB limit: refused from its size, unread. */
  mkdir(BUILD_DIR "/test-out", 0755);
  mkdir(WORK, 0755);
  int fd = open(WORK "/sparse.scene", O_WRONLY | O_CREAT | O_TRUNC, 0644);
  cr_assert(fd >= 0 && ftruncate(fd, 3l << 30) == 0 && close(fd) == 0);
  Check c = CHECK(REL_STEP " --scene", DOC);
  check_case(&c, "a 3 GiB scene file", WORK, "--quiet -o $OUT --scene sparse.scene", 1,
             "parser: cannot read 'sparse.scene': larger than 2147483647 bytes, the limit "
             "of a scene file\n", 0);
#if !REL_ASAN
  /* Under a 1 GiB address-space limit a 1 GiB file cannot be held: refused,
   * never parsed truncated. (Not under AddressSanitizer, which needs more.) */
  cr_assert(truncate(WORK "/sparse.scene", 1l << 30) == 0);
  check_case(&c, "a 1 GiB file under a 1 GiB address-space limit", WORK,
             "--quiet -o $OUT --scene sparse.scene", 1,
             "parser: cannot read 'sparse.scene': Cannot allocate memory\n", 1l << 30);
#endif
  remove(WORK "/sparse.scene");
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
