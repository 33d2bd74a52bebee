/* A scene text over 4 MB that uses every statement and every light type,
 * read as the program reads it (parser_load_text: with the speed pack, its
 * sphere lines read straight from the text) and by the general path alone
 * (sphere_line_on off): both must give the same scene, and hold every line
 * the test wrote. The statements and light types are taken from the parser's
 * own messages, so a statement added to the parser and not to this test
 * fails here. docs/scene-format.md, "Statements"; docs/extending.md. */
#include "parse_capture.h"
#include "check.h"

#include <stdlib.h>

#include "app/parser.h"
#include "reader/sphere_line.h"
#include "same_instance.h"

#define DOC "docs/extending.md, \"Adding a shape\""

/* One block of lines, written BLOCKS times (k: the block's number, for
 * values that differ from block to block). Shapes name the material of the
 * block after theirs, defined later: references resolved after the merge. */
static int block(char *out, size_t size, int k)
{
  float x = 0.001f * (float)k;
  return snprintf(out, size,
                  "material m%d diffuse 0.5 0.25 0.125 specular 0.1 0.2 0.3 shininess %d\n"
                  "sphere center %g 1 -2 radius 0.5 material m%d\n"
                  "plane point 0 %g 0 normal 0 1 0.5 material m%d\n"
                  "disc center %g 2 -3 normal 1 1 0 radius 0.25 material m%d\n"
                  "light point position %g 5 1 power 10 20 30 radius 0.5\n"
                  "light directional direction -1 -2 -%g irradiance 0.1 0.2 0.3\n"
                  "light area corner %g 4 -1 edge1 1 0 0 edge2 0 0 1 power 5 5 5\n"
                  "# a comment line, then a blank one\n\n",
                  k, k % 100, x, k + 1, -x, k + 1, x, k + 1, x, 1.0f + x, x);
}
enum { SHAPES_PER_BLOCK = 3, LIGHTS_PER_BLOCK = 3 };

/* The once-statements, written once, in the middle of the text. */
static const char ONCE[] = "film 320 240\n"
                           "camera eye 0 2 8 center 0 0.5 0 up 0 1 0 fov 50 focal 2\n"
                           "ambient 0.1 0.2 0.3\n"
                           "background 0.3 0.2 0.1\n"
                           "samples 9\n"
                           "light_samples 4\n";

/* The text: BLOCKS blocks, ONCE after the first half, then the last
 * block's material (which the last block's shapes name). */
static char *scene_text(int blocks, size_t *len)
{
  size_t cap = (size_t)blocks * 600 + sizeof ONCE + 128, n = 0;
  char *text = malloc(cap);
  cr_assert(text, "out of memory");
  for (int k = 0; k < blocks; k++) {
    if (k == blocks / 2)
      n += (size_t)snprintf(text + n, cap - n, "%s", ONCE);
    n += (size_t)block(text + n, cap - n, k);
  }
  n += (size_t)snprintf(text + n, cap - n, "material m%d diffuse 1 1 1\n", blocks);
  *len = n;
  return text;
}

/* The words an unknown word's message lists (`text` is one such word on a
 * line, `after` what the message says before its list). */
static int listed_words(const char *text, const char *after, char words[][24], int max)
{
  char msg[512];
  bool ok = parse_captured(text, strlen(text), msg, sizeof msg);
  const char *list = strstr(msg, after);
  cr_assert(!ok && list, "parser_load_text: expected a message with '%s' for '%s', got %s",
            after, text, msg);
  list += strlen(after);
  int n = 0;
  while (n < max && *list && *list != ')') {
    size_t len = strcspn(list, ",)");
    snprintf(words[n++], sizeof words[0], "%.*s", (int)len, list);
    list += len + (list[len] == ',' ? 2 : 0);
  }
  return n;
}

Test(large_scene, every_statement_arrives_through_the_large_text_path)
{
  char statements[32][24], types[16][24];
  int n_statements = listed_words("teapot\n", "a statement (", statements, 32);
  int n_types = listed_words("light teapot\n", "a light type (", types, 16);
  int blocks = 16000;
  size_t len;
  char *text = scene_text(blocks, &len);
  Check c = CHECK("parser_load_text", DOC);
  CHECK_REQUIRE(&c, len > ((size_t)4 << 20), "the test's scene text: expected more than "
                "4 MB (the large-text path), got %zu bytes", len);
  for (int k = 0; k < n_statements; k++) {
    char line[64];
    snprintf(line, sizeof line, "\n%.23s ", statements[k]);
    CHECK_THAT(&c, strstr(text, line) || !strncmp(text, line + 1, strlen(line) - 1),
               "the parser reads a '%s' statement, which this test's scene text does not "
               "use: add a line of it to block() or ONCE in tests/test_large_scene.c",
               statements[k]);
  }
  for (int k = 0; k < n_types; k++) {
    char line[64];
    snprintf(line, sizeof line, "\nlight %.23s ", types[k]);
    CHECK_THAT(&c, strstr(text, line) != NULL, "the parser reads a 'light %s', which this "
               "test's scene text does not use: add a line of it to block()", types[k]);
  }

  Scene fast, whole;
  scene_init(&fast);
  scene_init(&whole);
  bool ok_fast = parser_load_text("large.scene", text, len, &fast);
  sphere_line_on = false;
  bool ok_whole = parser_load_text("large.scene", text, len, &whole);
  sphere_line_on = true;
  CHECK_REQUIRE(&c, ok_fast && ok_whole, "the large scene text: expected both parses to "
                "succeed, got %d with the pack's sphere lines, %d without", ok_fast, ok_whole);

  /* Every line arrived (counted from what the test wrote). */
  CHECK_INT(&c, blocks + 1, fast.n_materials, "materials of the large text");
  CHECK_INT(&c, blocks * LIGHTS_PER_BLOCK, fast.n_lights, "lights of the large text");
  CHECK_INT(&c, blocks * SHAPES_PER_BLOCK, fast.n_shapes, "shapes of the large text");
  int spheres = 0, planes = 0, discs = 0;
  for (int k = 0; k < fast.n_shapes; k++) {
    spheres += fast.instances[k].shape == SHAPE_SPHERE;
    planes += fast.instances[k].shape == SHAPE_PLANE;
    discs += fast.instances[k].shape == SHAPE_DISC;
  }
  CHECK_INT(&c, blocks, spheres, "spheres of the large text");
  CHECK_INT(&c, blocks, planes, "planes of the large text");
  CHECK_INT(&c, blocks, discs, "discs of the large text");
  CHECK_INT(&c, 320, fast.width, "film 320 240, written halfway: width");
  CHECK_INT(&c, 9, fast.samples, "samples 9, written halfway");
  CHECK_INT(&c, 4, fast.light_samples, "light_samples 4, written halfway");
  CHECK_VEC(&c, vec_make(0.1f, 0.2f, 0.3f), fast.ambient, 0.0, "ambient, written halfway");
  CHECK_VEC(&c, vec_make(0.3f, 0.2f, 0.1f), fast.background, 0.0, "background, halfway");
  CHECK_VEC(&c, vec_make(0, 2, 8), fast.camera.eye, 0.0, "camera eye, written halfway");

  /* And as the one-pass parse has it, line by line. */
  CHECK_THAT(&c, fast.width == whole.width && fast.height == whole.height &&
                     fast.samples == whole.samples &&
                     fast.light_samples == whole.light_samples &&
                     !memcmp(&fast.camera, &whole.camera, sizeof fast.camera) &&
                     !memcmp(&fast.ambient, &whole.ambient, sizeof fast.ambient) &&
                     !memcmp(&fast.background, &whole.background, sizeof fast.background),
             "the once-statements: expected the one-pass parse's values");
  CHECK_REQUIRE(&c, fast.n_materials == whole.n_materials && fast.n_lights == whole.n_lights &&
                    fast.n_instances == whole.n_instances,
                "counts: expected the one-pass parse's %d materials, %d lights, %d "
                "instances, got %d, %d, %d", whole.n_materials, whole.n_lights,
                whole.n_instances, fast.n_materials, fast.n_lights, fast.n_instances);
  for (int k = 0; k < whole.n_materials; k++)
    CHECK_THAT(&c, !memcmp(&fast.materials[k], &whole.materials[k], sizeof *fast.materials),
               "material %d (%s): expected the one-pass parse's", k, whole.materials[k].name);
  for (int k = 0; k < whole.n_lights; k++)
    CHECK_THAT(&c, !memcmp(&fast.lights[k], &whole.lights[k], sizeof *fast.lights),
               "light %d: expected the one-pass parse's", k);
  for (int k = 0; k < whole.n_instances; k++)
    CHECK_THAT(&c, same_instance(&fast.instances[k], &whole.instances[k]),
               "instance %d (a %s): expected the one-pass parse's", k,
               scene_shape_name(whole.instances[k].shape));
  CHECK_DONE(&c);
  scene_free(&fast);
  scene_free(&whole);
  free(text);
}
