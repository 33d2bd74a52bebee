/* The parse of a large scene in pieces at once (fast/reader/pieces.c)
 * against the one-piece parse: the same scene, or the same message, for
 * every scene file of the repository. docs/reliability.md, "Large scenes". */
#define _DEFAULT_SOURCE /* mkstemp */
#include "capture.h"
#include "check.h"

#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "app/parser.h"
#include "app/parser_state.h"
#include "reader/pieces.h"
#include "reader/sphere_line.h"
#include "same_instance.h"

static bool same_instances(const Instance *a, const Instance *b, int n)
{
  for (int k = 0; k < n; k++)
    if (!same_instance(&a[k], &b[k]))
      return false;
  return true;
}

/* A scene's contents as bytes, for comparing two parses. */
static bool same_scene(const Scene *a, const Scene *b)
{
  return a->width == b->width && a->height == b->height && a->samples == b->samples &&
         a->light_samples == b->light_samples &&
         memcmp(&a->camera, &b->camera, sizeof a->camera) == 0 &&
         memcmp(&a->ambient, &b->ambient, sizeof a->ambient) == 0 &&
         memcmp(&a->background, &b->background, sizeof a->background) == 0 &&
         a->n_materials == b->n_materials && a->n_lights == b->n_lights &&
         a->n_instances == b->n_instances && a->n_shapes == b->n_shapes &&
         (a->n_materials == 0 || memcmp(a->materials, b->materials,
                                        sizeof *a->materials * (size_t)a->n_materials) == 0) &&
         (a->n_lights == 0 || memcmp(a->lights, b->lights,
                                     sizeof *a->lights * (size_t)a->n_lights) == 0) &&
         same_instances(a->instances, b->instances, a->n_instances);
}

/* Two parses agree: both fail with the same message, or both build the same
 * scene (and print nothing different). */
static bool same_parse(bool ok_a, const char *err_a, const Scene *a, bool ok_b,
                       const char *err_b, const Scene *b)
{
  return ok_a == ok_b && strcmp(err_a, err_b) == 0 && (!ok_a || same_scene(a, b));
}

/* What pieces_load prints and builds for `text` in `chunks` pieces. */
static bool parse_in_pieces(const char *text, size_t len, int chunks, Scene *s, char *err,
                            size_t size)
{
  FILE *tmp = tmpfile();
  cr_assert(tmp);
  capture_begin(tmp);
  scene_init(s);
  bool ok = pieces_load("t.scene", text, len, s, chunks);
  capture_end();
  rewind(tmp);
  err[fread(err, 1, size - 1, tmp)] = '\0';
  fclose(tmp);
  return ok;
}

/* Every scene of scenes/ and tests/bad/scenes/ parsed whole and in 2 to 9
 * pieces (cut at lines, so that a second `film`, a material defined twice or
 * used before its definition often fall in two pieces): the same scene, or
 * the same message. */
Test(parse_pieces, pieces_in_parallel_parse_as_the_whole)
{
  static const char *const dirs[] = {"scenes", "tests/bad/scenes"};
  Check c = CHECK("pieces_load", "docs/reliability.md, \"Large scenes\"");
  for (int d = 0; d < 2; d++) {
    DIR *dir = opendir(dirs[d]);
    cr_assert(dir, "no %s", dirs[d]);
    for (struct dirent *e; (e = readdir(dir));) {
      if (!strstr(e->d_name, ".scene"))
        continue;
      char path[300], whole_err[512], piece_err[512];
      snprintf(path, sizeof path, "%s/%.256s", dirs[d], e->d_name);
      FILE *f = fopen(path, "rb");
      cr_assert(f);
      static char text[1 << 16];
      size_t len = fread(text, 1, sizeof text, f);
      fclose(f);
      Scene whole, pieces;
      bool ok = parse_in_pieces(text, len, 1, &whole, whole_err, sizeof whole_err);
      for (int chunks = 2; chunks <= 9; chunks++) {
        int reparses = pieces_reparses;
        bool ok_p = parse_in_pieces(text, len, chunks, &pieces, piece_err, sizeof piece_err);
        CHECK_THAT(&c, same_parse(ok, whole_err, &whole, ok_p, piece_err, &pieces),
                   "%.100s in %d pieces: expected %s%.200s, got %s%.200s", path, chunks,
                   ok ? "the whole parse's scene" : "the whole parse's error: ", whole_err,
                   ok_p ? (ok ? "a different scene" : "a scene") : "", piece_err);
        CHECK_THAT(&c, !ok || pieces_reparses == reparses,
                   "%.100s in %d pieces: a valid scene, expected the pieces to parse it "
                   "(pieces_reparses unchanged), got it parsed again whole", path, chunks);
        scene_free(&pieces);
      }
      scene_free(&whole);
    }
    closedir(dir);
  }
  CHECK_DONE(&c);
}

/* Shapes that name materials defined only further down, so that in every
 * piece but the last the names are forward references (each piece keeps each
 * name once, docs/reliability.md, "Large scenes"), and, when `undefined`, one
 * name that is never defined: the same scene, or the same message, in 2 to 9
 * pieces as whole. */
static void forward_references(Check *c, bool undefined)
{
  static char text[1 << 16];
  size_t len = 0;
  len += (size_t)snprintf(text + len, sizeof text - len, "film 8 6\n");
  for (int k = 0; k < 600; k++)
    len += (size_t)snprintf(text + len, sizeof text - len,
                            "sphere center %d 0 -5 radius 0.5 material m%d\n", k, k % 7);
  if (undefined)
    len += (size_t)snprintf(text + len, sizeof text - len,
                            "sphere center 0 1 -5 radius 0.5 material nowhere\n");
  for (int k = 0; k < 7; k++)
    len += (size_t)snprintf(text + len, sizeof text - len, "material m%d diffuse 0.%d 0.5 0.5\n",
                            k, k + 1);
  char whole_err[512], piece_err[512];
  Scene whole, pieces;
  bool ok = parse_in_pieces(text, len, 1, &whole, whole_err, sizeof whole_err);
  CHECK_THAT(c, ok == !undefined && (undefined || whole.n_instances == 600),
             "forward references%s, whole: expected %s, got %s%.200s",
             undefined ? " and an undefined name" : "", undefined ? "an error" : "600 shapes",
             ok ? "a scene" : "", whole_err);
  for (int k = 0; ok && k < whole.n_instances; k++)
    CHECK_THAT(c, whole.instances[k].material == k % 7,
               "forward references, whole: shape %d: expected material %d, got %d", k, k % 7,
               whole.instances[k].material);
  for (int chunks = 2; chunks <= 9; chunks++) {
    int reparses = pieces_reparses;
    bool ok_p = parse_in_pieces(text, len, chunks, &pieces, piece_err, sizeof piece_err);
    CHECK_THAT(c, same_parse(ok, whole_err, &whole, ok_p, piece_err, &pieces),
               "forward references in %d pieces: expected %s%.200s, got %s%.200s", chunks,
               ok ? "the whole parse's scene" : "the whole parse's error: ", whole_err,
               ok_p ? (ok ? "a different scene" : "a scene") : "", piece_err);
    CHECK_THAT(c, !ok || pieces_reparses == reparses,
               "forward references in %d pieces: a valid scene, expected the pieces to "
               "parse it, got it parsed again whole", chunks);
    if (ok_p)
      scene_free(&pieces);
  }
  if (ok)
    scene_free(&whole);
}

Test(parse_pieces, forward_references_resolve_as_in_the_whole)
{
  Check c = CHECK("pieces_load", "docs/reliability.md, \"Large scenes\"");
  forward_references(&c, false);
  forward_references(&c, true);
  CHECK_DONE(&c);
}

/* Every piece writes its shapes in place, in room for one a line
 * (docs/reliability.md, "Large scenes"), the last line counted even without a
 * newline: a text of shapes only, its last line a shape with no newline,
 * parses in 2 to 9 pieces as whole, and never again whole. */
Test(parse_pieces, shapes_fit_their_pieces_room)
{
  Check c = CHECK("pieces_load", "docs/reliability.md, \"Large scenes\"");
  static char text[1 << 16];
  size_t len = (size_t)snprintf(text, sizeof text, "material m diffuse 1 1 1\n");
  for (int k = 0; k < 400; k++)
    len += (size_t)snprintf(text + len, sizeof text - len, "%ssphere center %d 0 -5 radius 0.5 "
                            "material m", k ? "\n" : "", k);
  char whole_err[512], piece_err[512];
  Scene whole, pieces;
  cr_assert(parse_in_pieces(text, len, 1, &whole, whole_err, sizeof whole_err), "%s", whole_err);
  for (int chunks = 2; chunks <= 9; chunks++) {
    int reparses = pieces_reparses;
    bool ok_p = parse_in_pieces(text, len, chunks, &pieces, piece_err, sizeof piece_err);
    CHECK_THAT(&c, ok_p && same_scene(&whole, &pieces) && pieces_reparses == reparses,
               "400 shapes, the last line without a newline, in %d pieces: expected the "
               "whole parse's scene from the pieces, got %s%s", chunks,
               !ok_p ? "an error" : same_scene(&whole, &pieces) ? "it" : "another scene",
               pieces_reparses == reparses ? "" : " only from parsing again whole");
    if (ok_p)
      scene_free(&pieces);
  }
  scene_free(&whole);
  CHECK_DONE(&c);
}

/* A header (the lines before the first sphere) and 3000 spheres in 2 to 9
 * pieces, as whole, and never again whole. When the spheres name only the
 * header's materials, each piece, given them (docs/reliability.md, "Large
 * scenes"), leaves no reference pending; when pieces define materials of their
 * own, used by later spheres, those keep their place after the header's. */
static void header_and_spheres(Check *c, bool own_materials)
{
  static char text[1 << 18];
  size_t len = (size_t)snprintf(text, sizeof text,
                                "film 8 6\nmaterial a diffuse 0.5 0.5 0.5\n"
                                "material b diffuse 0.1 0.2 0.3\n"
                                "plane point 0 -1 0 normal 0 1 0 material b\n");
  for (int k = 0; k < 3000; k++) {
    if (own_materials && k % 700 == 350)
      len += (size_t)snprintf(text + len, sizeof text - len, "material m%d diffuse 0.%d 0 0\n",
                              k, k % 9 + 1);
    const char *name = k % 2 ? "a" : "b";
    char own[16];
    if (own_materials && k % 3 == 0 && k > 350) {
      snprintf(own, sizeof own, "m%d", (k - 350) / 700 * 700 + 350);
      name = own;
    }
    len += (size_t)snprintf(text + len, sizeof text - len,
                            "sphere center %d 0 -5 radius 0.5 material %s\n", k, name);
  }
  cr_assert(len < sizeof text - 1);
  char whole_err[512], piece_err[512];
  Scene whole, pieces;
  cr_assert(parse_in_pieces(text, len, 1, &whole, whole_err, sizeof whole_err), "%s", whole_err);
  for (int chunks = 2; chunks <= 9; chunks++) {
    int reparses = pieces_reparses, pending = pieces_pending;
    bool ok_p = parse_in_pieces(text, len, chunks, &pieces, piece_err, sizeof piece_err);
    CHECK_THAT(c, ok_p && same_scene(&whole, &pieces) && pieces_reparses == reparses,
               "a header and 3000 spheres%s, in %d pieces: expected the whole parse's scene "
               "from the pieces, got %s%s", own_materials ? " (pieces define materials)" : "",
               chunks, !ok_p ? "an error" : same_scene(&whole, &pieces) ? "it" : "another scene",
               pieces_reparses == reparses ? "" : " only from parsing again whole");
    CHECK_THAT(c, own_materials || pieces_pending == pending,
               "3000 spheres naming the header's materials, in %d pieces: expected 0 "
               "references left pending by the pieces (each given the header's materials), "
               "got %d", chunks, pieces_pending - pending);
    if (ok_p)
      scene_free(&pieces);
  }
  scene_free(&whole);
}

Test(parse_pieces, header_materials_reach_every_piece)
{
  Check c = CHECK("pieces_load", "docs/reliability.md, \"Large scenes\"");
  header_and_spheres(&c, false);
  header_and_spheres(&c, true);
  CHECK_DONE(&c);
}

/* A scene file of 8 MB or more is mapped, not read into a buffer: nothing
 * follows its last byte. Such files, one ending in a newline and one whose
 * last line has none and ends exactly at a page boundary, parse as their
 * text does. */
Test(parse_pieces, a_mapped_file_parses_as_its_text, .timeout = 120)
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
  double v = ((double)(next(s) % 2000001) - 1000000.0) / pow(10.0, (double)(next(s) % 9));
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

/* `text` parsed with sphere_line (sphere_line_on) in `pieces` pieces and
 * by the general path whole: one check that they give the same scene or
 * the same message (`what` names the text). Whether the general path read
 * a scene. */
static bool fast_as_general(Check *c, const char *text, size_t len, int pieces,
                            const char *what)
{
  char err_f[512], err_g[512];
  Scene a, b;
  sphere_line_on = true;
  bool ok_f = parse_in_pieces(text, len, pieces, &a, err_f, sizeof err_f);
  sphere_line_on = false;
  bool ok_g = parse_in_pieces(text, len, 1, &b, err_g, sizeof err_g);
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
Test(parse_pieces, sphere_lines_read_fast_parse_as_the_general_path, .timeout = 60)
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
    good += fast_as_general(&c, text, len, 1, what);
  }
  sphere_line_on = true;
  CHECK_THAT(&c, good > 5000 && good < 18000, "expected both good and bad lines among the "
             "20000, found %d good", good);
  CHECK_DONE(&c);
}

/* Many sphere lines in one text, their material names from a set that
 * sphere_line remembers in part (the last 8 it found): names of 1 to 20
 * bytes, some a prefix of another or the same length and equal to it in
 * their first 8 or 15 bytes; lines that end in a space, a '\r', a comment
 * or an extra word, or at the end of the text; the same scene, or the same
 * message, as the general path. */
Test(parse_pieces, sphere_lines_naming_many_materials_parse_as_the_general_path,
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
    char what[64]; /* the fast path in 1 to 3 pieces, each remembering its own names */
    snprintf(what, sizeof what, "text %d (%d sphere lines, %d pieces)", k, lines, 1 + k % 3);
    good += fast_as_general(&c, text, len, 1 + k % 3, what);
  }
  sphere_line_on = true;
  CHECK_THAT(&c, good > 900 && good < 1400, "expected both good and bad texts among the "
             "1500, found %d good", good);
  CHECK_DONE(&c);
}
