/* Tests of the scene-file parser (step 02 on): every statement into the
 * expected Scene, the limits accepted at their edges, and every documented
 * error with its exact FILE:LINE:COL message (columns counted by hand, from
 * 1). docs/scene-format.md. */
#include "capture.h"
#include "check.h"
#include "statements.h"

#include <stdlib.h>
#include <unistd.h>

#include "app/parser.h"
#include "shapes.h"

#define DOC "docs/scene-format.md, \"Statements\""
#define DOC_ERR "docs/scene-format.md, \"Errors\""
#define DOC_LIM "docs/scene-format.md, \"Limits\""

static const char FULL[] =
    "# every statement, keywords in any order, a material used before its\n"
    "# definition, comments and blank lines\n"
    "\n"
    "sphere material red radius 1 center 0 1 0   # comment after a statement\n"
    "film 800 600\n"
    "camera fov 45 up 0 1 0 center 0 0.5 0 eye 0 2 8\n"
    "\t ambient 0.1 0.2 0.3\n"
    "background 0.1 0.15 0.3\r\n"
    "material red   ambient 0.8 0.1 0.1 diffuse 0.8 0.1 0.2 specular 0.5 0.5 0.5 shininess 64\n"
    "material floor diffuse 0.7 0.6 0.5\n"
    "plane normal 0 2 0 point 0 -1 0 material floor\n"
    "light point position 4 6 4 power 60 50 40\n"
    "light directional irradiance 0.3 0.3 0.3 direction -1 -2 -1\n"
    "light area corner -1 5 -1 edge1 2 0 0 edge2 0 0 2 power 60 60 60\n"
    "samples 16\n"
    "light_samples 9\n";

Test(parser, every_statement_into_the_scene)
{
  Scene s;
  scene_init(&s);
  Check c = CHECK("parser_load_string", DOC);
  cr_assert(parser_load_string("full.scene", FULL, &s), "parser_load_string refused a "
            "scene using every statement (its message is above)\n  read " DOC);
  CHECK_INT(&c, 800, s.width, "film 800 600: width");
  CHECK_INT(&c, 600, s.height, "film 800 600: height");
  CHECK_VEC(&c, vec_make(0, 2, 8), s.camera.eye, 0.0, "camera eye 0 2 8");
  CHECK_VEC(&c, vec_make(0, 0.5f, 0), s.camera.center, 0.0, "camera center 0 0.5 0");
  CHECK_VEC(&c, vec_make(0, 1, 0), s.camera.up, 0.0, "camera up 0 1 0");
  CHECK_NEAR(&c, 45.0, s.camera.fov_y_deg, 0.0, "camera fov 45");
  CHECK_NEAR(&c, 1.0, s.camera.focal, 0.0, "camera without focal: the default 1");
  CHECK_VEC(&c, vec_make(0.1f, 0.2f, 0.3f), s.ambient, 0.0, "an indented ambient line");
  CHECK_VEC(&c, vec_make(0.1f, 0.15f, 0.3f), s.background, 0.0, "background with a CRLF end");
  CHECK_INT(&c, 16, s.samples, "samples 16");
  CHECK_INT(&c, 9, s.light_samples, "light_samples 9");

  cr_assert(s.n_materials == 2 && s.n_instances == 2 && s.n_lights == 3,
            "parser_load_string: expected 2 materials, 2 shapes, 3 lights, got %d, %d, %d",
            s.n_materials, s.n_instances, s.n_lights);
  const Material *red = &s.materials[0], *floor = &s.materials[1];
  CHECK_THAT(&c, strcmp(red->name, "red") == 0 && strcmp(floor->name, "floor") == 0,
             "material names in file order: expected red, floor, got %s, %s", red->name,
             floor->name);
  CHECK_VEC(&c, vec_make(0.8f, 0.1f, 0.1f), red->ambient, 0.0, "material red: ambient");
  CHECK_VEC(&c, vec_make(0.8f, 0.1f, 0.2f), red->diffuse, 0.0, "material red: diffuse");
  CHECK_VEC(&c, vec_make(0.5f, 0.5f, 0.5f), red->specular, 0.0, "material red: specular");
  CHECK_NEAR(&c, 64.0, red->shininess, 0.0, "material red: shininess");
  CHECK_VEC(&c, vec_make(0.7f, 0.6f, 0.5f), floor->ambient, 0.0,
            "material floor without ambient: ambient defaults to diffuse");
  CHECK_VEC(&c, vec_make(0, 0, 0), floor->specular, 0.0, "material floor: specular 0");

  const Instance *sph = &s.instances[0], *pl = &s.instances[1];
  CHECK_INT(&c, SHAPE_SPHERE, sph->shape, "first shape: a sphere");
  CHECK_VEC(&c, vec_make(0, 1, 0), sph->sphere.center, 0.0, "sphere center");
  CHECK_NEAR(&c, 1.0, sph->sphere.radius, 0.0, "sphere radius");
  CHECK_INT(&c, 0, sph->material, "the sphere's material, red, defined after it: index 0");
  CHECK_INT(&c, SHAPE_PLANE, pl->shape, "second shape: a plane");
  CHECK_VEC(&c, vec_make(0, -1, 0), pl->plane.point, 0.0, "plane point");
  CHECK_VEC(&c, vec_make(0, 1, 0), pl->plane.normal, 0.0, "plane normal 0 2 0, normalised");
  CHECK_INT(&c, 1, pl->material, "the plane's material, floor: index 1");

  const Light *pt = &s.lights[0], *dir = &s.lights[1], *area = &s.lights[2];
  CHECK_VEC(&c, vec_make(4, 6, 4), pt->position, 0.0, "point light position");
  CHECK_VEC(&c, vec_make(60, 50, 40), pt->power, 0.0, "point light power");
  /* direction (-1, -2, -1) / sqrt(6). */
  float k = (float)(1.0L / sqrtl(6.0L));
  CHECK_VEC(&c, vec_make(-k, -2 * k, -k), dir->direction, 1e-7,
            "directional light: direction -1 -2 -1 over sqrt(6)");
  /* edge1 x edge2 = (2,0,0) x (0,0,2) = (0*2 - 0*0, 0*0 - 2*2, 2*0 - 0*0) = (0,-4,0). */
  CHECK_VEC(&c, vec_make(0, -1, 0), area->quad.normal, 0.0, "area light normal");
  CHECK_NEAR(&c, 4.0, area->quad.area, 0.0, "area light area |(2,0,0) x (0,0,2)|");
  CHECK_DONE(&c);
  scene_free(&s);
}

Test(parser, empty_text_gives_the_defaults)
{
  Scene s;
  scene_init(&s);
  Check c = CHECK("parser_load_string", DOC);
  cr_assert(parser_load_string("empty.scene", "# nothing\n\n   \n", &s));
  CHECK_INT(&c, 800, s.width, "empty scene: film width default");
  CHECK_INT(&c, 600, s.height, "empty scene: film height default");
  CHECK_INT(&c, 1, s.samples, "empty scene: samples default");
  CHECK_VEC(&c, vec_make(0, 0, -1), s.camera.center, 0.0, "empty scene: camera center default");
  CHECK_INT(&c, 0, s.n_instances + s.n_lights + s.n_materials, "empty scene: nothing in it");
  scene_free(&s);
}

static float width(const Scene *s) { return (float)s->width; }
static float samples(const Scene *s) { return (float)s->samples; }
static float ambient_r(const Scene *s) { return s->ambient.x; }
static float focal(const Scene *s) { return s->camera.focal; }
static float eye_x(const Scene *s) { return s->camera.eye.x; }
static float radius(const Scene *s) { return s->instances[0].sphere.radius; }
static float direction_x(const Scene *s) { return s->lights[0].direction.x; }

/* Each row: a text the parser must accept, and one value it must read. */
Test(parser, limits_themselves_are_accepted)
{
  static const struct {
    const char *text, *what;
    float (*get)(const Scene *);
    float want;
  } ok[] = {
      {"film 16384 1024\n", "the largest film side", width, 16384.0f},
      {"samples 65536\n", "the largest sample count", samples, 65536.0f},
      {"ambient 1.17549435e-38 0 -0\n", "FLT_MIN, the smallest normal float", ambient_r,
       1.17549435e-38f},
      {"camera focal 1e-6\n", "the smallest focal distance", focal, 1e-6f},
      {"camera focal 1e6\n", "the largest focal distance", focal, 1e6f},
      {"camera fov 179.9 eye 1e18 0 0 center -1e18 0 0\n", "a coordinate of 1e18", eye_x,
       1e18f},
      {"sphere center 0 0 0 radius 1e-18 material m\nmaterial m\n", "the smallest radius",
       radius, 1e-18f},
      {"sphere center 0 0 0 radius 1e18 material m\nmaterial m\n", "the largest radius",
       radius, 1e18f},
      {"light directional direction 1e-18 0 0 irradiance 1 1 1\n",
       "a direction of length 1e-18", direction_x, 1.0f},
      {"\xef\xbb\xbf" "film 8 6\n", "a UTF-8 byte-order mark before the first line", width,
       8.0f},
  };
  Check c = CHECK("parser_load_string", DOC_LIM);
  for (size_t k = 0; k < sizeof ok / sizeof ok[0]; k++) {
    Scene s;
    scene_init(&s);
    bool parsed = parser_load_string("t.scene", ok[k].text, &s);
    CHECK_THAT(&c, parsed, "%s must be accepted: %s", ok[k].what, ok[k].text);
    if (parsed)
      CHECK_ULPS(&c, ok[k].want, ok[k].get(&s), 0, "%s: the value read", ok[k].what);
    scene_free(&s);
  }
  CHECK_DONE(&c);
}

/* Parse `text` as t.scene, expect failure, return what it printed on stderr
 * (caller frees). */
static char *parse_error(const char *text, size_t len)
{
  FILE *tmp = tmpfile();
  cr_assert(tmp);
  capture_begin(tmp);
  Scene s;
  scene_init(&s);
  bool ok = parser_load_text("t.scene", text, len, &s);
  capture_end();
  if (ok)
    scene_free(&s);
  long n = ftell(tmp);
  char *buf = calloc((size_t)n + 1, 1);
  rewind(tmp);
  cr_assert(buf && fread(buf, 1, (size_t)n, tmp) == (size_t)n);
  fclose(tmp);
  Check c = CHECK("parser_load_text", DOC_ERR);
  CHECK_THAT(&c, !ok, "parsed without error:\n%s", text);
  CHECK_THAT(&c, s.n_instances == 0 && s.materials == NULL,
             "after an error the scene must be freed (scene_free), got %d instances",
             s.n_instances);
  return buf;
}

/* One error case: the text (NUL-terminated unless len is given) and the one
 * line it must print. */
typedef struct Bad {
  const char *text, *message;
  size_t len;
} Bad;

static void expect_errors(const Bad *bad, size_t n, const char *doc)
{
  Check c = CHECK("parser_load_string", doc);
  for (size_t k = 0; k < n; k++) {
    size_t len = bad[k].len ? bad[k].len : strlen(bad[k].text);
    char *got = parse_error(bad[k].text, len);
    char want[640];
    snprintf(want, sizeof want, "%s\n", bad[k].message);
    CHECK_THAT(&c, strcmp(got, want) == 0, "for the scene text\n    %s\n  expected "
               "stderr  %s  got stderr       %s", bad[k].text, want, got);
    free(got);
  }
  CHECK_DONE(&c);
}

#define ERRORS(doc, ...)                                                         \
  do {                                                                           \
    static const Bad bad_[] = {__VA_ARGS__};                                     \
    expect_errors(bad_, sizeof bad_ / sizeof bad_[0], doc);                      \
  } while (0)


Test(parser, unknown_words_suggest_the_nearest)
{
  ERRORS(DOC_ERR,
    {"sphre center 0 0 0 radius 1 material m\n",
     "t.scene:1:1: expected a statement " STATEMENTS ", found 'sphre'; did you mean 'sphere'?", 0},
    /* Line and column count comments, blank lines and indentation. */
    {"# comment\n\n  lihgt point position 0 0 0 power 1 1 1\n",
     "t.scene:3:3: expected a statement " STATEMENTS ", found 'lihgt'; did you mean 'light'?", 0},
    {"teapot 1 2 3\n", "t.scene:1:1: expected a statement " STATEMENTS ", found 'teapot'", 0},
    /* s=1 center=8 0=15,17,19 radius=21 1=28 materal=30 */
    {"sphere center 0 0 0 radius 1 materal m\n",
     "t.scene:1:30: expected a sphere keyword (center, radius, material), found 'materal'; "
     "did you mean 'material'?", 0},
    {"camera eye 0 0 5 lookat 0 0 0\n",
     "t.scene:1:18: expected a camera keyword (eye, center, up, fov, focal), found 'lookat'", 0},
    {"light pointt position 0 0 0 power 1 1 1\n",
     "t.scene:1:7: expected a light type " LIGHT_TYPES ", found 'pointt'; did you "
     "mean 'point'?", 0},
    {"light point position 0 0 0 powr 1 1 1\n",
     "t.scene:1:28: expected a point light keyword (position, power, radius), found 'powr'; "
     "did you mean 'power'?", 0});
}

Test(parser, missing_and_extra_values)
{
  ERRORS(DOC_ERR,
    {"sphere center 0 0 radius 1 material m\n",
     "t.scene:1:19: expected 3 numbers after 'center', found 'radius'", 0},
    {"sphere center 0 0 0 radius\n",
     "t.scene:1:27: expected a number after 'radius', found end of line", 0},
    {"sphere center 0 0 0 radius 1\n",
     "t.scene:1:29: expected 'material' in this sphere statement, found end of line", 0},
    {"film 800\n", "t.scene:1:9: expected the film height, found end of line", 0},
    {"ambient 0.1 0.1\n",
     "t.scene:1:16: expected 3 numbers >= 0 after 'ambient', found end of line", 0},
    {"light\n", "t.scene:1:6: expected a light type " LIGHT_TYPES ", found end of line", 0},
    {"material\n", "t.scene:1:9: expected a material name, found end of line", 0},
    {"sphere center 0 0 0 1 radius 1 material m\n",
     "t.scene:1:21: expected a sphere keyword, found an extra value '1'", 0},
    {"film 10 10 5\n", "t.scene:1:12: expected end of line, found an extra value '5'", 0},
    {"background 0 0 0 0\n", "t.scene:1:18: expected end of line, found an extra value '0'", 0},
    {"samples 4 4\n", "t.scene:1:11: expected end of line, found an extra value '4'", 0});
}

Test(parser, non_finite_and_tiny_numbers)
{
  ERRORS(DOC_ERR,
    {"sphere center 0 0 0 radius inf material m\n",
     "t.scene:1:28: expected a number after 'radius', found a non-finite value 'inf'", 0},
    {"sphere center 0 nan 0 radius 1 material m\n",
     "t.scene:1:17: expected 3 numbers after 'center', found a non-finite value 'nan'", 0},
    {"background 1e999 0 0\n",
     "t.scene:1:12: expected 3 numbers >= 0 after 'background', found a non-finite value "
     "'1e999'", 0},
    {"camera fov -INFINITY\n",
     "t.scene:1:12: expected a number after 'fov', found a non-finite value '-INFINITY'", 0},
    /* Below FLT_MIN: a subnormal, and an underflow to zero. */
    {"background 1e-40 0 0\n",
     "t.scene:1:12: expected 3 numbers >= 0 after 'background', found '1e-40', below the "
     "smallest normal float 1.2e-38 (write 0)", 0},
    {"sphere radius 1e-50 center 0 0 0 material m\n",
     "t.scene:1:15: expected a number after 'radius', found '1e-50', below the smallest "
     "normal float 1.2e-38 (write 0)", 0},
    {"ambient -0.1 0 0\n", "t.scene:1:9: expected 3 numbers >= 0 after 'ambient', found '-0.1'", 0},
    {"material m diffuse 0.5 -0.5 0.5\n",
     "t.scene:1:24: expected 3 numbers >= 0 after 'diffuse', found '-0.5'", 0},
    {"material m shininess -1\n", "t.scene:1:22: expected shininess >= 0, found '-1'", 0});
}

Test(parser, shapes_and_lights_out_of_range)
{
  ERRORS(DOC_LIM,
    {"sphere center 0 0 0 radius 0 material m\n",
     "t.scene:1:28: expected a radius > 0, found '0'", 0},
    {"sphere center 0 1 0 radius -1 material red\n",
     "t.scene:1:28: expected a radius > 0, found '-1'", 0},
    {"light point position 0 0 0 power 1 1 1 radius 0\n",
     "t.scene:1:47: expected a radius > 0, found '0'", 0},
    {"sphere center 0 0 0 radius 2e18 material m\n",
     "t.scene:1:28: expected a radius from 1e-18 to 1e18 (its square must fit in a float), "
     "found '2e18'", 0},
    /* sphere=1 center=8 2e38=15 */
    {"sphere center 2e38 0 0 radius 1 material m\n",
     "t.scene:1:15: expected a coordinate from -1e18 to 1e18 after 'center' (squares and "
     "differences must fit in a float), found '2e38'", 0},
    /* plane=1 point=7 0=13,15,17 normal=19 0=26 */
    {"plane point 0 0 0 normal 0 0 0 material m\n",
     "t.scene:1:26: expected a non-zero normal, found '0 0 0'", 0},
    {"plane point 0 0 0 normal 0 1e-30 0 material m\n",
     "t.scene:1:26: expected a normal of length 1e-18 to 1e18 (it is normalised in float), "
     "found '0 1e-30 0'", 0},
    /* light=1 area=7 corner=12 0=19,21,23 edge1=25 0=31 */
    {"light area corner 0 0 0 edge1 0 0 0 edge2 0 0 1 power 1 1 1\n",
     "t.scene:1:31: expected a non-zero edge1, found '0 0 0'", 0},
    {"light area corner 0 0 0 edge1 1 0 0 edge2 0 0 0 power 1 1 1\n",
     "t.scene:1:43: expected a non-zero edge2, found '0 0 0'", 0},
    {"light area corner 0 0 0 edge1 1 0 0 edge2 -2 0 0 power 1 1 1\n",
     "t.scene:1:43: expected edge2 not parallel to edge1 (a light with an area), found "
     "parallel edges", 0},
    /* light=1 area=7 corner=12 0=19,21,23 edge1=25 1e9=31 0=35,37 edge2=39 0=45 */
    {"light area corner 0 0 0 edge1 1e9 0 0 edge2 0 0 1e10 power 1 1 1\n",
     "t.scene:1:45: expected edges whose area |edge1 x edge2| is from 1e-18 to 1e18 (in "
     "float), found 1e+19", 0},
    /* Too large for the float computation itself. */
    {"light area corner 0 0 0 edge1 1e10 0 0 edge2 0 0 1e10 power 1 1 1\n",
     "t.scene:1:46: expected edges whose area |edge1 x edge2| is from 1e-18 to 1e18 (in "
     "float), found inf", 0},
    {"light directional direction 0 0 0 irradiance 1 1 1\n",
     "t.scene:1:29: expected a non-zero direction, found '0 0 0'", 0},
    {"light directional direction 0 -1e-30 -0.5e-30 irradiance 1 1 1\n",
     "t.scene:1:29: expected a direction of length 1e-18 to 1e18 (it is normalised in "
     "float), found '0 -1e-30 -0.5e-30'", 0});
}

Test(parser, camera_out_of_range)
{
  ERRORS(DOC_LIM,
    {"camera fov 0\n", "t.scene:1:12: expected a field of view in (0, 180) degrees, found '0'", 0},
    {"camera eye 0 0 5 fov 180\n",
     "t.scene:1:22: expected a field of view in (0, 180) degrees, found '180'", 0},
    {"camera focal 0\n", "t.scene:1:14: expected a focal distance > 0, found '0'", 0},
    {"camera focal 1e20\n", "t.scene:1:14: expected a focal distance from 1e-6 to 1e6 (the "
     "rays must stay finite in float), found '1e20'", 0},
    {"camera focal 1e-30\n", "t.scene:1:14: expected a focal distance from 1e-6 to 1e6 "
     "(the rays must stay finite in float), found '1e-30'", 0},
    /* camera=1 eye=8 1=12,14,16 center=18 1=25 */
    {"camera eye 1 2 3 center 1 2 3\n",
     "t.scene:1:25: expected eye and center at different points, found both at (1 2 3)", 0},
    /* camera=1 eye=8 0=12,14,16 center=18 0=25 -5=27 0=30 up=32 0=35 */
    {"camera eye 0 0 0 center 0 -5 0 up 0 1 0\n",
     "t.scene:1:35: expected an up vector not parallel to the view direction, found up "
     "(0 1 0)", 0},
    {"camera up 0 0 0\n", "t.scene:1:11: expected a non-zero up vector, found '0 0 0'", 0},
    {"camera eye -3e38 0 0 center 3e38 0 0\n",
     "t.scene:1:12: expected a coordinate from -1e18 to 1e18 after 'eye' (squares and "
     "differences must fit in a float), found '-3e38'", 0});
}

Test(parser, materials_defined_once_and_used_defined)
{
  ERRORS(DOC_ERR,
    /* sphere=1 center=8 0=15,17,19 radius=21 1=28 material=30 blu=39 */
    {"material red diffuse 1 0 0\nsphere center 0 0 0 radius 1 material blu\n",
     "t.scene:2:39: expected a defined material name (red), found 'blu'", 0},
    {"sphere center 0 0 0 radius 1 material rde\nmaterial red diffuse 1 0 0\n",
     "t.scene:1:39: expected a defined material name (red), found 'rde'; did you mean 'red'?", 0},
    {"plane point 0 0 0 normal 0 1 0 material floor\n",
     "t.scene:1:41: expected a defined material name, found 'floor' (the file defines no "
     "material)", 0},
    {"material red diffuse 1 0 0\nmaterial red diffuse 0 1 0\n",
     "t.scene:2:10: expected a new material name, found 'red' (already defined)", 0},
    {"material 9lives diffuse 1 1 1\n",
     "t.scene:1:10: expected a material name (letters, digits, '_', at most 63 characters), "
     "found '9lives'", 0});
}

Test(parser, statements_once_and_keywords_once)
{
  ERRORS(DOC_ERR,
    {"film 10 10\nfilm 20 20\n",
     "t.scene:2:1: expected one 'film' statement, found a second (first at line 1)", 0},
    /* The column of an indented second statement is its own. */
    {"camera fov 40\n   camera fov 50\n",
     "t.scene:2:4: expected one 'camera' statement, found a second (first at line 1)", 0},
    {"sphere radius 1 center 0 0 0 radius 2 material m\n",
     "t.scene:1:30: expected each sphere keyword once, found a second 'radius' (first at "
     "column 8)", 0});
}

Test(parser, counts_in_range)
{
  ERRORS(DOC_LIM,
    {"film 16385 10\n",
     "t.scene:1:6: expected the film width, a whole number from 1 to 16384, found '16385'", 0},
    {"film 10 0\n", "t.scene:1:9: expected the film height, a whole number from 1 to 16384, "
     "found '0'", 0},
    {"film 12.5 10\n",
     "t.scene:1:6: expected the film width, a whole number from 1 to 16384, found '12.5'", 0},
    /* 16384 * 1025 = 16793600 > 2^24 = 16777216. */
    {"film 16384 1025\n", "t.scene:1:6: expected at most 16777216 pixels, found 16384x1025", 0},
    {"samples 0\n", "t.scene:1:9: expected the number of samples, a whole number from 1 to "
     "65536, found '0'", 0},
    {"samples 65537\n", "t.scene:1:9: expected the number of samples, a whole number from 1 "
     "to 65536, found '65537'", 0},
    {"light_samples 2.5\n", "t.scene:1:15: expected the number of light samples, a whole "
     "number from 1 to 65536, found '2.5'", 0},
    {"samples 1e9\n", "t.scene:1:9: expected the number of samples, a whole number from 1 "
     "to 65536, found '1e9'", 0});
}

Test(parser, bytes_that_are_not_text)
{
  ERRORS("docs/scene-format.md, \"Errors\"",
    {"film 10 10\nfilm\x01 10 10\n", "t.scene:2:5: expected text, found the control byte 0x01", 0},
    {"film 10 10\nfilm 1\0 10\n", "t.scene:2:7: expected text, found the control byte 0x00", 22},
    /* A NUL byte is refused even in a comment. */
    {"film 10 10 # \0\n", "t.scene:1:14: expected text, found the control byte 0x00", 15},
    /* A byte-order mark anywhere but at the start is part of a word, shown
     * as the bytes it is made of (it would not show). */
    {"film 8 6\n\xef\xbb\xbf" "film 8 6\n",
     "t.scene:2:1: expected a statement " STATEMENTS ", found '\\xef\\xbb\\xbffilm'", 0},
    /* Valid UTF-8 shows as itself; invalid bytes as \xNN. */
    {"f\xc3\xafl\xc3\xa9 8 6\n",
     "t.scene:1:1: expected a statement " STATEMENTS ", found 'f\xc3\xafl\xc3\xa9'", 0},
    {"film 8 6\nfilm\xe9 8 6\n",
     "t.scene:2:1: expected a statement " STATEMENTS ", found 'film\\xe9'; did you mean 'film'?", 0});
}

/* The messages of the file reader, run with stderr captured. */
static void expect_file_error(const char *path, const char *message)
{
  FILE *tmp = tmpfile();
  cr_assert(tmp);
  capture_begin(tmp);
  Scene s;
  scene_init(&s);
  bool ok = parser_load_file(path, &s);
  capture_end();
  char buf[512] = "";
  rewind(tmp);
  size_t n = fread(buf, 1, sizeof buf - 1, tmp);
  buf[n] = '\0';
  fclose(tmp);
  Check c = CHECK("parser_load_file", "docs/scene-format.md, \"Errors\"");
  CHECK_THAT(&c, !ok, "reading '%s' must fail", path);
  CHECK_THAT(&c, strcmp(buf, message) == 0, "reading '%s'\n  expected stderr  %s  got "
             "stderr       %s", path, message, buf);
}

Test(parser, unreadable_files_name_the_reason)
{
  expect_file_error(BUILD_DIR "/no-such.scene",
                    "parser: cannot read '" BUILD_DIR "/no-such.scene': No such file or "
                    "directory\n");
  expect_file_error("tests", "parser: cannot read 'tests': Is a directory\n");
  expect_file_error("/dev/zero", "/dev/zero:1:1: expected text, found the control byte 0x00\n");
}
