/* Huge and pathological inputs of the bad-input suite, generated here, not
 * committed (docs/reliability.md, "The bad-input suite"): 10^6 lines, 10 MB
 * lines and words, 5 x 10^5 words on a line, 2 x 10^5 materials, files too
 * large to read. */
#define _DEFAULT_SOURCE /* realpath, truncate */
#include "bad_run.h"
#include "statements.h"

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
  /* 2 x 10^5 materials, each used by one sphere: the timeout fails a lookup
   * whose time grows with the number of names (quadratic in all). */
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

