/* A scene text parsed in parts (parser_part_parse, parser_parts_join) and
 * joined, against the one-pass parse (parser_load_whole): the same scene,
 * value by value, or a failure exactly where the one-pass parse fails; and
 * the speed pack's reader (fast/reader/parts.c, pack_parse) on large texts:
 * the same scene, or the one-pass parse's message, whichever piece an error
 * falls in. docs/performance.md, "A large scene text in parts". */
#include "parse_capture.h"
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "app/parser.h"
#include "grow.h"
#include "reader/parts.h"
#include "same_instance.h"
#include "scene.h"

#define DOC "docs/performance.md, \"A large scene text in parts\""

/* A scene whose lines a cut may part: materials used before and after
 * their definition, every once-statement, lights of each kind, every shape,
 * comments and blank lines; a byte-order mark first. */
static const char SCENE[] =
    "\xef\xbb\xbf# a scene cut at every line\n"
    "film 64 48\n"
    "material red diffuse 0.8 0.1 0.1 specular 0.5 0.5 0.5 shininess 32\n"
    "sphere center 0 1 -5 radius 1 material red\n"
    "sphere center 1 1 -5 radius 0.5 material late\n"
    "camera eye 0 2 8 center 0 0.5 0 up 0 1 0 fov 50 focal 2\n"
    "\n"
    "light point position 1 5 1 power 10 20 30 radius 0.5\n"
    "material blue diffuse 0.1 0.1 0.8\n"
    "plane point 0 -1 0 normal 0 1 0.5 material blue\n"
    "ambient 0.1 0.2 0.3\n"
    "sphere center 2 1 -5 radius 0.25 material red\n"
    "disc center 0.25 2 -3 normal 1 1 0 radius 0.25 material late\n"
    "light directional direction -1 -2 -1 irradiance 0.1 0.2 0.3\n"
    "background 0.3 0.2 0.1\n"
    "material late diffuse 0.2 0.9 0.2\n"
    "sphere center 3 1 -5 radius 0.125 material blue\n"
    "samples 9\n"
    "light area corner 0 4 -1 edge1 1 0 0 edge2 0 0 1 power 5 5 5\n"
    "light_samples 4\n"
    "sphere center 4 1 -5 radius 0.5 material late   # the last line\n";

/* Lines that make the scene wrong when one of them follows SCENE's line
 * `at`: each an error the one-pass parse reports, some that no part alone
 * can see (a second definition or once-statement in another part, a name
 * nowhere defined). */
static const char *const WRONG[] = {
    "material red diffuse 1 1 1\n",
    "material late diffuse 1 1 1\n",
    "material gold diffuse 1 1 1\n",
    "film 32 24\n",
    "camera eye 0 0 1 center 0 0 0\n",
    "samples 4\n",
    "light_samples 2\n",
    "ambient 0 0 0\n",
    "background 0 0 0\n",
    "sphere center 0 0 0 radius 1 material nowhere\n",
    "sphere center 0 0 0 radius -1 material red\n",
    "spere center 0 0 0 radius 1 material red\n",
};

/* Line starts of text[0 .. len): at[0 .. n), at[0] = 0. */
static int line_starts(const char *text, size_t len, size_t *at, int max)
{
  int n = 0;
  at[n++] = 0;
  for (size_t k = 0; k + 1 < len && n < max; k++)
    if (text[k] == '\n')
      at[n++] = k + 1;
  return n;
}

static int lines_in(const char *text, size_t from, size_t to)
{
  int n = 0;
  for (size_t k = from; k < to; k++)
    n += text[k] == '\n';
  return n + (to > from && text[to - 1] != '\n');
}

/* `text` cut at cut[0 .. n_cuts) (line starts, rising), each part given
 * part 0 or not, joined: true with `scene` filled, or false, as
 * parser_parts_join answers (or a part's parse). */
static bool parse_in_parts(const char *text, size_t len, const size_t *cut, int n_cuts,
                           bool given, Scene *scene)
{
  size_t from[8];
  int n = 0;
  from[n++] = 0;
  for (int k = 0; k < n_cuts; k++)
    from[n++] = cut[k];
  from[n] = len;
  int room[9] = {0};
  for (int k = 0; k < n; k++)
    room[k + 1] = room[k] + lines_in(text, from[k], from[k + 1]);
  Instance *shapes = malloc(grow_capacity((size_t)room[n]) * sizeof *shapes);
  cr_assert(shapes, "out of memory");
  ParserPart *part[8] = {NULL};
  bool ok = true;
  for (int k = 0; k < n; k++) {
    part[k] = parser_part_parse("t.scene", text, from[k], from[k + 1],
                                given && k > 0 ? part[0] : NULL, shapes + room[k],
                                room[k + 1] - room[k]);
    ok = ok && part[k];
  }
  scene_init(scene);
  ok = ok && parser_parts_join(part, n, shapes, scene);
  for (int k = 0; k < n; k++)
    parser_part_free(part[k]);
  if (!ok)
    free(shapes);
  return ok;
}

/* One check: `text` in parts as the one-pass parse has it (the same scene,
 * or both fail). */
static void parts_as_whole(Check *c, const char *text, size_t len, const size_t *cut,
                           int n_cuts, bool given, const char *what)
{
  Scene whole, parts;
  scene_init(&whole);
  FILE *quiet = tmpfile();
  cr_assert(quiet, "tmpfile failed");
  capture_begin(quiet);
  bool ok_whole = parser_load_whole("t.scene", text, len, &whole);
  capture_end();
  fclose(quiet);
  bool ok_parts = parse_in_parts(text, len, cut, n_cuts, given, &parts);
  CHECK_THAT(c, ok_whole == ok_parts && (!ok_whole || same_scene(&whole, &parts)),
             "%s, cut at byte %zu%s%s (given the first part's materials: %s): expected "
             "the one-pass parse's %s, got %s", what, cut[0], n_cuts > 1 ? " and " : "",
             n_cuts > 1 ? "more" : "", given ? "yes" : "no",
             ok_whole ? "scene" : "failure",
             !ok_parts ? "a failure" : ok_whole ? "a different scene" : "a scene");
  if (ok_whole)
    scene_free(&whole);
  if (ok_parts)
    scene_free(&parts);
}

Test(scene_parts, parts_cut_at_every_line_join_as_the_one_pass_parse)
{
  Check c = CHECK("parser_parts_join", DOC);
  size_t len = sizeof SCENE - 1, at[64];
  int n = line_starts(SCENE, len, at, 64);
  for (int i = 1; i < n; i++)
    for (int j = i; j < n; j++)
      for (int given = 0; given < 2; given++) {
        size_t cut[2] = {at[i], at[j]};
        parts_as_whole(&c, SCENE, len, cut, i == j ? 1 : 2, given, "the scene");
      }
  CHECK_DONE(&c);
}

/* A part holds at most the shapes its room has: one more, and its parse
 * fails (quietly; the one-pass parse would then run), a room of none
 * included. */
Test(scene_parts, a_part_fails_when_its_room_is_full)
{
  static const char TEXT[] = "material red diffuse 1 0 0\n"
                             "sphere center 0 0 -5 radius 1 material red\n"
                             "sphere center 2 0 -5 radius 1 material red\n";
  size_t len = sizeof TEXT - 1;
  Instance room[2];
  Check c = CHECK("parser_part_parse", DOC);
  for (int n_room = 0; n_room <= 2; n_room++) {
    ParserPart *part = parser_part_parse("t.scene", TEXT, 0, len, NULL,
                                         n_room > 0 ? room : NULL, n_room);
    if (n_room < 2)
      CHECK_THAT(&c, part == NULL, "two spheres in a room of %d: the part must fail, got a part "
                 "of %d shapes", n_room, part ? parser_part_shapes(part) : 0);
    else
      CHECK_THAT(&c, part && parser_part_shapes(part) == 2, "two spheres in a room of 2: "
                 "a part of 2 shapes expected, got %d", part ? parser_part_shapes(part) : -1);
    parser_part_free(part);
  }
  CHECK_DONE(&c);
}

/* Each wrong line after each line of the scene, the text cut before the
 * wrong line, after it, and far from it: the parts fail where the one-pass
 * parse fails (and where it does not: a later definition of a name nowhere
 * defined yet is no error when it comes first). */
Test(scene_parts, an_error_in_any_part_fails_the_join)
{
  Check c = CHECK("parser_parts_join", DOC);
  size_t len0 = sizeof SCENE - 1, at[64];
  int n = line_starts(SCENE, len0, at, 64);
  char text[sizeof SCENE + 128];
  for (size_t w = 0; w < sizeof WRONG / sizeof *WRONG; w++)
    for (int i = 1; i <= n; i++) {
      size_t split = i < n ? at[i] : len0, wl = strlen(WRONG[w]);
      memcpy(text, SCENE, split);
      memcpy(text + split, WRONG[w], wl);
      memcpy(text + split + wl, SCENE + split, len0 - split);
      size_t len = len0 + wl;
      char what[160];
      snprintf(what, sizeof what, "the scene with '%.*s' at line %d", (int)wl - 1, WRONG[w],
               i + 1);
      size_t before[1] = {split}, after[1] = {split + wl}, both[2] = {split, split + wl};
      size_t far[1] = {i < n / 2 ? at[n - 1] + wl : at[1]};
      for (int given = 0; given < 2; given++) {
        if (split > 0)
          parts_as_whole(&c, text, len, before, 1, given, what);
        if (split + wl < len)
          parts_as_whole(&c, text, len, after, 1, given, what);
        if (split > 0 && split + wl < len)
          parts_as_whole(&c, text, len, both, 2, given, what);
        parts_as_whole(&c, text, len, far, 1, given, what);
      }
    }
  CHECK_DONE(&c);
}

/* A large text as the program's files are: a header of materials and lights,
 * then `n` sphere lines, with SCENE's lines (its materials renamed by the
 * caller's `tag`) among them every `every` lines. */
static char *large_text(int n, int every, size_t *len)
{
  size_t cap = (size_t)n * 64 + (size_t)(n / every + 1) * sizeof SCENE + 4096;
  char *text = malloc(cap);
  cr_assert(text, "out of memory");
  size_t at = (size_t)snprintf(text, cap, "material floor diffuse 0.7 0.7 0.7\n"
                               "material gold diffuse 0.8 0.6 0.15 specular 0.9 0.8 0.5\n"
                               "light point position 4 6 4 power 40 40 40\n");
  int block = 0;
  for (int k = 0; k < n; k++) {
    if (k % every == every / 2) { /* SCENE's lines, its names made new */
      const char *s = SCENE + 3; /* after its byte-order mark */
      for (const char *line = s; *line;) {
        size_t l = strcspn(line, "\n") + 1;
        if (strncmp(line, "film", 4) && strncmp(line, "camera", 6) &&
            strncmp(line, "ambient", 7) && strncmp(line, "background", 10) &&
            strncmp(line, "samples", 7) && strncmp(line, "light_samples", 13)) {
          for (size_t j = 0; j < l; j++) {
            text[at++] = line[j];
            /* red, blue, late -> red<b>, blue<b>, late<b> */
            static const char *const names[] = {" red", " blue", " late"};
            for (int m = 0; m < 3; m++) {
              size_t nl = strlen(names[m]);
              if (j + 1 >= nl && !strncmp(line + j + 1 - nl, names[m], nl) &&
                  (line[j + 1] == ' ' || line[j + 1] == '\n'))
                at += (size_t)snprintf(text + at, cap - at, "%d", block);
            }
          }
        }
        line += l;
      }
      block++;
    }
    at += (size_t)snprintf(text + at, cap - at,
                           "sphere center %.6g %.6g -%.6g radius %.6g material %s\n",
                           -6.0 + (k % 1000) * 0.012, 0.003 + (k % 7) * 0.0001,
                           8.0 - (k / 1000) * 0.016, 0.003 + (k % 7) * 0.0001,
                           k % 3 ? "gold" : "floor");
  }
  at += (size_t)snprintf(text + at, cap - at, "film 320 240\nsamples 4\n");
  *len = at;
  return text;
}

Test(scene_parts, a_large_text_in_pieces_is_the_one_pass_scene, .timeout = 120)
{
  Check c = CHECK("parts_load", DOC);
  size_t len;
  char *text = large_text(60000, 5000, &len);
  Scene whole;
  scene_init(&whole);
  CHECK_REQUIRE(&c, parser_load_whole("t.scene", text, len, &whole),
                "the test's large text: expected the one-pass parse to read it");
  for (int pieces = 2; pieces <= 9; pieces++) {
    Scene parts;
    scene_init(&parts);
    bool ok = parts_load("t.scene", text, len, &parts, pieces);
    CHECK_THAT(&c, ok && same_scene(&whole, &parts), "%zu bytes in %d pieces: expected the "
               "one-pass parse's scene (%d instances, %d materials), got %s", len, pieces,
               whole.n_instances, whole.n_materials, ok ? "another" : "none");
    if (ok)
      scene_free(&parts);
  }
  scene_free(&whole);
  free(text);
  CHECK_DONE(&c);
}

/* A text over PARTS_PIECE_MIN * 2 bytes with one wrong line in it, at
 * places in the first, a middle and the last piece (and in the header):
 * what parser_load_text prints (the speed pack's reader first, when the
 * build has it) is what the one-pass parse prints, FILE:LINE:COL and text. */
Test(scene_parts, an_error_in_any_piece_reads_as_the_one_pass_message, .timeout = 240)
{
  Check c = CHECK("parser_load_text", DOC);
  size_t len;
  char *text = large_text(90000, 30000, &len);
  CHECK_REQUIRE(&c, len > 2 * (size_t)PARTS_PIECE_MIN, "the test's large text: expected "
                "over %d bytes, got %zu", 2 * PARTS_PIECE_MIN, len);
  char *wrong = malloc(len + 256);
  cr_assert(wrong, "out of memory");
  static const double place[] = {0.0, 0.001, 0.2, 0.5, 0.77, 0.999, 1.0};
  for (size_t w = 0; w < sizeof WRONG / sizeof *WRONG; w++)
    for (size_t p = 0; p < sizeof place / sizeof *place; p++) {
      /* the line start nearest the place */
      size_t at = (size_t)(place[p] * (double)len);
      while (at > 0 && at < len && text[at - 1] != '\n')
        at++;
      if (at > len)
        at = len;
      size_t wl = strlen(WRONG[w]);
      memcpy(wrong, text, at);
      memcpy(wrong + at, WRONG[w], wl);
      memcpy(wrong + at + wl, text + at, len - at);
      char got[512], want[512];
      bool ok = parse_captured(wrong, len + wl, got, sizeof got);
      FILE *tmp = tmpfile();
      cr_assert(tmp, "tmpfile failed");
      capture_begin(tmp);
      Scene s;
      scene_init(&s);
      bool ok_whole = parser_load_whole("t.scene", wrong, len + wl, &s);
      capture_end();
      if (ok_whole)
        scene_free(&s);
      rewind(tmp);
      want[fread(want, 1, sizeof want - 1, tmp)] = '\0';
      fclose(tmp);
      CHECK_THAT(&c, ok == ok_whole && strcmp(got, want) == 0,
                 "'%.*s' at byte %zu of %zu: expected the one-pass parse's %s%s, got %s%s",
                 (int)wl - 1, WRONG[w], at, len + wl, ok_whole ? "scene" : "message ", want,
                 ok ? "a scene" : "", got);
    }
  free(wrong);
  free(text);
  CHECK_DONE(&c);
}
