/* The large scene's fast reading (the speed pack's sphere lines,
 * fast/reader/sphere_line.c, and a mapped file) against the general path:
 * the same scene, or the same message. docs/reliability.md, "Large
 * scenes". */
#define _DEFAULT_SOURCE /* mkstemp */
#include "capture.h"
#include "check.h"

#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "app/parser.h"
#include "app/parser_state.h"
#include "reader/sphere_line.h"
#include "same_instance.h"

/* Two parses agree: both fail with the same message, or both build the same
 * scene (and print nothing different). */
static bool same_parse(bool ok_a, const char *err_a, const Scene *a, bool ok_b,
                       const char *err_b, const Scene *b)
{
  return ok_a == ok_b && strcmp(err_a, err_b) == 0 && (!ok_a || same_scene(a, b));
}

/* What parser_load_text prints and builds for `text`. */
static bool parse_captured_text(const char *text, size_t len, Scene *s, char *err, size_t size)
{
  FILE *tmp = tmpfile();
  cr_assert(tmp);
  capture_begin(tmp);
  scene_init(s);
  bool ok = parser_load_text("t.scene", text, len, s);
  capture_end();
  rewind(tmp);
  err[fread(err, 1, size - 1, tmp)] = '\0';
  fclose(tmp);
  return ok;
}

Test(fast_reader, a_mapped_file_parses_as_its_text, .timeout = 120)
{
  Check c = CHECK("parser_load_file", "docs/scene-format.md, \"Errors\"");
  size_t cap = 10u << 20;
  char *text = malloc(cap);
  cr_assert(text);
  for (int last_newline = 0; last_newline < 2; last_newline++) {
    size_t len = (size_t)snprintf(text, cap, "film 8 6\nmaterial m diffuse 1 1 1\n");
    for (int k = 0; len < (9u << 20); k++)
      len += (size_t)snprintf(text + len, cap - len, "sphere center %d.25 0 -5 radius 0.5 "
                              "material m\n", k % 1000);
    /* Spaces before the last word, so that the file ends at a 4096-byte
     * boundary right after it (or after its newline). */
    size_t tail = last_newline ? 1 : 0, want = (len + 64 + 4095) / 4096 * 4096;
    len += (size_t)snprintf(text + len, cap - len, "sphere center 1 2 -3 radius 0.5 material");
    while (len + 1 + tail < want)
      text[len++] = ' ';
    text[len++] = 'm';
    if (tail)
      text[len++] = '\n';
    char path[] = "/tmp/rt-mapped-XXXXXX";
    int fd = mkstemp(path);
    cr_assert(fd >= 0);
    cr_assert(write(fd, text, len) == (ssize_t)len);
    close(fd);
    Scene from_file, from_text;
    scene_init(&from_file);
    scene_init(&from_text);
    bool ok_f = parser_load_file(path, &from_file);
    bool ok_t = parser_load_text(path, text, len, &from_text);
    unlink(path);
    CHECK_THAT(&c, ok_f && ok_t && len % 4096 == 0 && same_scene(&from_file, &from_text) &&
               from_file.instances[from_file.n_instances - 1].sphere.center.y == 2.0f,
               "a %zu-byte file %s a final newline: expected the scene of its text, got %s",
               len, last_newline ? "with" : "without",
               !ok_f ? "an error" : !ok_t ? "an error from the text" : "a different scene");
    if (ok_f)
      scene_free(&from_file);
    if (ok_t)
      scene_free(&from_text);
  }
  free(text);
  CHECK_DONE(&c);
}

/* A small generator (xorshift64*), seeded: the same lines every run. */
static uint64_t next(uint64_t *s)
{
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return *s * 2685821657736338717ull;
}

static const char *pick(uint64_t *s, const char *const *from, size_t n)
{
  return from[next(s) % n];
}

/* A number as a scene might write it, or a word close to one. */
static void number_word(uint64_t *s, char *out, size_t size)
{
  static const char *const odd[] = {
      "1e18", "-1e18", "1.0000001e18", "1e19", "1e-18", "9.9e-19", "0", "-0", "+2", ".5",
      "5.", "1e", "1e+", "--1", "1.2.3", "1,5", "0x1p3", "inf", "nan", "1e-40", "1e39",
      "12345678901234567890", "0.000000000000000000000001", "1E3", "2e-3x", "-", ".",
      "1e0000000000000000000000000000000000000000000000000000000000000001", /* 66 bytes */
      "00000000000000000000000000000000000000000000000000000000000001.5"};  /* 64 */
  if (next(s) % 10 == 0) {
    snprintf(out, size, "%s", pick(s, odd, sizeof odd / sizeof *odd));
    return;
  }
  double digits = (double)(next(s) % 2000001) - 1000000.0;
  double v = digits / pow(10.0, (double)(next(s) % 9));
  static const char *const fmt[] = {"%g", "%.9g", "%.3f", "%e", "%.17g"};
  snprintf(out, size, pick(s, fmt, sizeof fmt / sizeof *fmt), v);
}

/* A sphere line, often the one sphere_line reads, often one a byte or a
 * word away from it (spaces, tabs, '\r', a comment, another order, another
 * keyword, a name that is not one, an undefined or later-defined material). */
static size_t sphere_variant(uint64_t *s, char *out, size_t size)
{
  static const char *const names[] = {"m", "late", "nowhere", "_x9", "9x", "a-b", "M",
      "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa",  /* 63 */
      "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa", /* 64 */
      "caf\xc3\xa9", "m#c", "m\tx"};
  static const char *const gaps[] = {" ", " ", " ", " ", " ", " ", "  ", "\t", " \t"};
  bool spaced = next(s) % 8 == 0; /* gaps other than one space */
  char x[96], y[96], z[96], r[96];
  number_word(s, x, sizeof x);
  number_word(s, y, sizeof y);
  number_word(s, z, sizeof z);
  number_word(s, r, sizeof r);
  if (next(s) % 4)
    snprintf(r, sizeof r, "%g", (double)(next(s) % 1000 + 1) / 100.0);
  const char *w[9] = {"sphere", "center", x, y, z, "radius", r, "material",
                      next(s) % 3 ? names[next(s) % 2] : pick(s, names, sizeof names / sizeof *names)};
  int n = 9;
  switch (next(s) % 24) {
  case 0: w[0] = "Sphere"; break;
  case 1: w[1] = "radius", w[5] = "center"; break;
  case 2: n = 8; break;
  case 3: n = 7; break;
  case 4: w[7] = "materials"; break;
  default: break;
  }
  size_t len = 0;
  if (next(s) % 16 == 0)
    out[len++] = ' ';
  for (int k = 0; k < n; k++)
    len += (size_t)snprintf(out + len, size - len, "%s%s",
                            k == 0 ? "" : spaced ? pick(s, gaps, 9) : " ", w[k]);
  static const char *const tails[] = {" ", "\r", " # note", "#x", " 1"};
  if (next(s) % 6 == 0)
    len += (size_t)snprintf(out + len, size - len, "%s", pick(s, tails, 5));
  return len;
}

/* `text` parsed with the pack's sphere lines (sphere_line_on) and by the
 * general path: one check that they give the same scene or the same message
 * (`what` names the text). Whether the general path read a scene. */
static bool fast_as_general(Check *c, const char *text, size_t len, const char *what)
{
  char err_f[512], err_g[512];
  Scene a, b;
  sphere_line_on = true;
  bool ok_f = parse_captured_text(text, len, &a, err_f, sizeof err_f);
  sphere_line_on = false;
  bool ok_g = parse_captured_text(text, len, &b, err_g, sizeof err_g);
  sphere_line_on = true;
  CHECK_THAT(c, same_parse(ok_g, err_g, &b, ok_f, err_f, &a),
             "%s:\n  expected (general path) %s%.200s\n  got (fast path)      %s%.200s", what,
             ok_g ? "a scene" : "the error ", err_g,
             ok_f ? (ok_g ? "a different scene" : "a scene") : "the error ", err_f);
  if (ok_f)
    scene_free(&a);
  if (ok_g)
    scene_free(&b);
  return ok_g;
}

/* The sphere lines that parser_statements reads straight from the text
 * (sphere_line) against the general path (sphere_line_on off): 20000
 * lines, each alone between a material defined before and one defined
 * after, with and without a final newline; the same scene, or the same
 * message. */
Test(fast_reader, sphere_lines_read_fast_parse_as_the_general_path, .timeout = 60)
{
  Check c = CHECK("parser_statements", "docs/reliability.md, \"Large scenes\"");
  uint64_t s = 0x243F6A8885A308D3ull;
  int good = 0;
  for (int k = 0; k < 20000; k++) {
    char line[512], text[1024];
    size_t n = sphere_variant(&s, line, sizeof line);
    bool newline = k % 2;
    size_t len = (size_t)snprintf(text, sizeof text, "film 8 6\nmaterial m diffuse 1 1 1\n"
                                  "%s%s", line, newline ? "\n" : "");
    if (k % 4 < 2) /* `late` defined after its use */
      len += (size_t)snprintf(text + len, sizeof text - len, "%smaterial late diffuse 1 1 1\n",
                              newline ? "" : "\n");
    char what[600];
    snprintf(what, sizeof what, "the line '%.*s'%s", (int)n, line,
             newline ? " and a newline" : "");
    good += fast_as_general(&c, text, len, what);
  }
  sphere_line_on = true;
  CHECK_THAT(&c, good > 5000 && good < 18000, "expected both good and bad lines among the "
             "20000, found %d good", good);
  CHECK_DONE(&c);
}

/* Many sphere lines in one text, their material names from a set that
 * the parser remembers in part (the last one): names of 1 to 20
 * bytes, some a prefix of another or the same length and equal to it in
 * their first 8 or 15 bytes; lines that end in a space, a '\r', a comment
 * or an extra word, or at the end of the text; the same scene, or the same
 * message, as the general path. */
Test(fast_reader, sphere_lines_naming_many_materials_parse_as_the_general_path,
     .timeout = 60)
{
  Check c = CHECK("parser_statements", "docs/reliability.md, \"Large scenes\"");
  static const char *const names[] = {
      "r", "red", "redd", "red_1", "green", "abcdefg", "abcdefgh", "abcdefghi",
      "abcdefghZZ", "abcdefghYY", "abcdefghijklmno", "abcdefghijklmnop", "abcdefghijklmnopq",
      "abcdefghijklmnopqrst",
      "gold", "white", "Blue", "x_9"};
  static const char *const other[] = {"undefined", "abcdefghijklmnox", "re", "9x", "late"};
  static const char *const tails[] = {"", "", "", "", "", "", " ", "\r", "#c", " x", " # c"};
  const int n_names = (int)(sizeof names / sizeof *names);
  uint64_t s = 0x13198A2E03707344ull;
  int good = 0;
  for (int k = 0; k < 1500; k++) {
    static char text[1 << 14];
    size_t len = (size_t)snprintf(text, sizeof text, "film 8 6\n");
    for (int m = 0; m < n_names; m++)
      len += (size_t)snprintf(text + len, sizeof text - len, "material %s diffuse 1 1 1\n",
                              names[m]);
    int lines = 1 + (int)(next(&s) % 40);
    bool odd = k % 3 == 0; /* a text with one line that is not right */
    int bad = (int)(next(&s) % (uint64_t)lines);
    for (int j = 0; j < lines; j++) {
      double x = ((double)(next(&s) % 2000001) - 1000000.0) / 1e5;
      double r = (double)(next(&s) % 100000 + 1) / 1e7;
      const char *name = names[next(&s) % (uint64_t)n_names];
      const char *tail = "";
      if (odd && j == bad) {
        if (next(&s) % 2)
          name = pick(&s, other, sizeof other / sizeof *other);
        else
          tail = pick(&s, tails, sizeof tails / sizeof *tails);
      }
      len += (size_t)snprintf(text + len, sizeof text - len,
                              "sphere center %.6g %.6g %.6g radius %.6g material %s%s%s", x, r,
                              -x / 3.0, r, name, tail, j + 1 < lines || k % 2 ? "\n" : "");
    }
    if (k % 4 == 1)
      len += (size_t)snprintf(text + len, sizeof text - len, "material late diffuse 1 1 1\n");
    char what[64];
    snprintf(what, sizeof what, "text %d (%d sphere lines)", k, lines);
    good += fast_as_general(&c, text, len, what);
  }
  sphere_line_on = true;
  CHECK_THAT(&c, good > 900 && good < 1400, "expected both good and bad texts among the "
             "1500, found %d good", good);
  CHECK_DONE(&c);
}
