/* A scene text over 4 MB that uses every statement and every light type,
 * read as the program reads it (parser_load_text: with the speed pack, its
 * sphere lines read straight from the text and, on two threads or more, the
 * text parsed in parts at once) and by the general path (sphere_line_on
 * off): both must give the same scene, and hold every line
 * the test wrote. Its lines are the examples of the parser's statement table
 * (parser_statement_example) and one of each light type (taken from the
 * parser's own message: a light type added to the parser and not to this
 * test fails here). docs/scene-format.md, "Statements"; docs/extending.md. */
#include "parse_capture.h"
#include "check.h"

#include <stdlib.h>

#include "app/parser.h"
#include "app/parser_state.h"
#include "reader/sphere_line.h"
#include "same_instance.h"
#include "scene.h"
#include "scene_index.h"
#include "surface.h"

#define DOC "docs/extending.md, \"Adding a shape\""

/* An example line of the statement table (parser_statement_example) with
 * its material `m` renamed: m<k> where the material statement defines it,
 * m<k + 1> where a shape names it (a material defined later: references
 * resolved after the merge). Returns its length, as snprintf. */
static int example_line(char *out, size_t size, const char *example, int k)
{
  bool defines = strncmp(example, "material ", 9) == 0;
  char line[512];
  cr_assert(strlen(example) < sizeof line - 32, "parser_statement_example: expected an "
            "example line under %zu bytes, got %zu: %s", sizeof line - 32, strlen(example),
            example);
  int n = 0;
  for (const char *w = example; *w;) {
    size_t len = strcspn(w, " ");
    bool named = len == 1 && *w == 'm' && n >= 9 && !strncmp(line + n - 9, "material ", 9);
    n += named ? snprintf(line + n, sizeof line - (size_t)n, "m%d", defines ? k : k + 1)
               : snprintf(line + n, sizeof line - (size_t)n, "%.*s", (int)len, w);
    w += len;
    if (*w == ' ')
      line[n++] = *w++;
  }
  line[n] = '\0';
  return snprintf(out, size, "%s\n", line);
}

/* One block of lines, written BLOCKS times (k: the block's number): the
 * example of every statement of the table that a file may repeat, each
 * light type, a comment and a blank line. With out NULL, only its length. */
static int block(char *out, size_t size, int k)
{
  size_t n = 0;
  for (int s = 0; s < parser_statement_count(); s++)
    if (!parser_statement_once(s))
      n += (size_t)example_line(out ? out + n : NULL, out ? size - n : 0,
                                parser_statement_example(s), k);
  float x = 0.001f * (float)k;
  n += (size_t)snprintf(out ? out + n : NULL, out ? size - n : 0,
                        "light directional direction -1 -2 -%g irradiance 0.1 0.2 0.3\n"
                        "light area corner %g 4 -1 edge1 1 0 0 edge2 0 0 1 power 5 5 5\n"
                        "# a comment line, then a blank one\n\n",
                        1.0f + x, x);
  return (int)n;
}

/* The once-statements' examples, written once, in the middle of the text.
 * With out NULL, only their length. */
static size_t once_lines(char *out, size_t size)
{
  size_t n = 0;
  for (int s = 0; s < parser_statement_count(); s++)
    if (parser_statement_once(s))
      n += (size_t)snprintf(out ? out + n : NULL, out ? size - n : 0, "%s\n",
                            parser_statement_example(s));
  return n;
}

/* The text: BLOCKS blocks, the once-statements after the first half, then
 * the last block's material (which the last block's shapes name). Its size
 * is measured first: a statement added to the table lengthens every block. */
static char *scene_text(int blocks, size_t *len)
{
  size_t cap = once_lines(NULL, 0) + 64;
  for (int k = 0; k < blocks; k++)
    cap += (size_t)block(NULL, 0, k);
  char *text = malloc(cap), *end = text;
  cr_assert(text, "out of memory");
  for (int k = 0; k < blocks; k++) {
    if (k == blocks / 2)
      end += once_lines(end, cap - (size_t)(end - text));
    end += block(end, cap - (size_t)(end - text), k);
  }
  end += snprintf(end, cap - (size_t)(end - text), "material m%d diffuse 1 1 1\n", blocks);
  *len = (size_t)(end - text);
  return text;
}

/* What one block holds, parsed alone: its materials, lights, and shapes of
 * each kind. */
typedef struct Counts {
  int materials, lights, shapes, kind[SHAPE_COUNT];
} Counts;

static Counts counts_of(const Scene *s)
{
  Counts c = {s->n_materials, s->n_lights, s->n_shapes, {0}};
  for (int k = 0; k < s->n_shapes; k++)
    c.kind[s->instances[k].shape]++;
  return c;
}

static Counts one_block(void)
{
  char text[4096];
  int n = block(text, sizeof text, 0);
  snprintf(text + n, sizeof text - (size_t)n, "material m1 diffuse 1 1 1\n");
  Scene s;
  scene_init(&s);
  cr_assert(parser_load_whole("block.scene", text, strlen(text), &s),
            "parser_load_whole: one block of the large text must parse (its message is "
            "above): the statement table's example lines (parser_statement_example)\n%s",
            text);
  Counts c = counts_of(&s);
  scene_free(&s);
  c.materials--; /* m1, defined for the block's shapes */
  return c;
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
  char types[16][24];
  int n_types = listed_words("light teapot\n", "a light type (", types, 16);
  int blocks = 16000;
  size_t len;
  char *text = scene_text(blocks, &len);
  Check c = CHECK("parser_load_text", DOC);
  CHECK_REQUIRE(&c, len > ((size_t)4 << 20), "the test's scene text: expected more than "
                "4 MB (the large-text path), got %zu bytes", len);
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
  Counts want = one_block(), got = counts_of(&fast);
  CHECK_INT(&c, blocks * want.materials + 1, got.materials, "materials of the large text");
  CHECK_INT(&c, blocks * want.lights, got.lights, "lights of the large text");
  CHECK_INT(&c, blocks * want.shapes, got.shapes, "shapes of the large text");
  for (int k = 0; k < SHAPE_COUNT; k++)
    CHECK_INT(&c, blocks * want.kind[k], got.kind[k], "%s instances of the large text",
              scene_shape_name((ShapeType)k));
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
