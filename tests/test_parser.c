/* Tests of the scene-file parser (step 02 on): every statement into the
 * expected Scene, and every documented error with its exact FILE:LINE:COL
 * message (columns counted by hand, from 1). docs/scene-format.md. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/parser.h"

static bool near3(vec3s v, float x, float y, float z)
{
  return fabsf(v.x - x) <= 1e-6f && fabsf(v.y - y) <= 1e-6f && fabsf(v.z - z) <= 1e-6f;
}

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
  cr_assert(parser_load_string("full.scene", FULL, &s));
  cr_expect(s.width == 800 && s.height == 600);
  cr_expect(near3(s.camera.eye, 0, 2, 8) && near3(s.camera.center, 0, 0.5f, 0) &&
            near3(s.camera.up, 0, 1, 0) && s.camera.fov_y_deg == 45.0f && s.camera.focal == 1.0f);
  cr_expect(near3(s.ambient, 0.1f, 0.2f, 0.3f) && near3(s.background, 0.1f, 0.15f, 0.3f));
  cr_expect(s.samples == 16 && s.light_samples == 9);

  cr_assert(s.n_materials == 2);
  const Material *red = &s.materials[0], *floor = &s.materials[1];
  cr_expect(strcmp(red->name, "red") == 0 && strcmp(floor->name, "floor") == 0);
  cr_expect(near3(red->ambient, 0.8f, 0.1f, 0.1f) && near3(red->diffuse, 0.8f, 0.1f, 0.2f) &&
            near3(red->specular, 0.5f, 0.5f, 0.5f) && red->shininess == 64.0f);
  /* Unspecified fields are 0, ambient defaults to diffuse. */
  cr_expect(near3(floor->diffuse, 0.7f, 0.6f, 0.5f) && near3(floor->ambient, 0.7f, 0.6f, 0.5f));
  cr_expect(near3(floor->specular, 0, 0, 0) && floor->shininess == 0.0f);

  cr_assert(s.n_instances == 2 && s.n_shapes == 2);
  const Instance *sph = &s.instances[0], *pl = &s.instances[1];
  cr_expect(sph->shape == SHAPE_SPHERE && near3(sph->sphere.center, 0, 1, 0) &&
            sph->sphere.radius == 1.0f && sph->material == 0 && sph->light == -1);
  cr_expect(pl->shape == SHAPE_PLANE && near3(pl->plane.point, 0, -1, 0) &&
            near3(pl->plane.normal, 0, 1, 0) && pl->material == 1);

  cr_assert(s.n_lights == 3);
  const Light *pt = &s.lights[0], *dir = &s.lights[1], *area = &s.lights[2];
  cr_expect(pt->type == LIGHT_POINT && near3(pt->position, 4, 6, 4) &&
            near3(pt->power, 60, 50, 40) && pt->radius == 0.0f);
  /* direction (-1, -2, -1) / sqrt(6). */
  float k = (float)(1.0L / sqrtl(6.0L));
  cr_expect(dir->type == LIGHT_DIRECTIONAL && near3(dir->direction, -k, -2 * k, -k) &&
            near3(dir->irradiance, 0.3f, 0.3f, 0.3f));
  /* edge1 x edge2 = (2,0,0) x (0,0,2) = (0*2 - 0*0, 0*0 - 2*2, 2*0 - 0*0) = (0,-4,0). */
  cr_expect(area->type == LIGHT_AREA && near3(area->quad.corner, -1, 5, -1) &&
            near3(area->quad.edge1, 2, 0, 0) && near3(area->quad.edge2, 0, 0, 2) &&
            near3(area->quad.normal, 0, -1, 0) && area->quad.area == 4.0f &&
            near3(area->power, 60, 60, 60));
  scene_free(&s);
}

Test(parser, empty_text_gives_the_defaults)
{
  Scene s;
  scene_init(&s);
  cr_assert(parser_load_string("empty.scene", "# nothing\n\n   \n", &s));
  cr_expect(s.width == 800 && s.height == 600 && s.samples == 1 && s.light_samples == 1);
  cr_expect(near3(s.background, 0, 0, 0) && near3(s.ambient, 0, 0, 0));
  cr_expect(near3(s.camera.eye, 0, 0, 0) && near3(s.camera.center, 0, 0, -1) &&
            s.camera.fov_y_deg == 45.0f);
  cr_expect(s.n_instances == 0 && s.n_lights == 0 && s.n_materials == 0);
  scene_free(&s);
}

Test(parser, limits_themselves_are_accepted)
{
  Scene s;
  scene_init(&s);
  cr_assert(parser_load_string("t.scene", "film 4096 4096\nsamples 65536\n"
                               "light point position 0 1 0 power 1 1 1 radius 0.5\n"
                               "ambient 1e-40 0 -0\n", &s));
  cr_expect(s.width == 4096 && s.height == 4096 && s.samples == 65536);
  cr_expect(s.lights[0].radius == 0.5f);
  cr_expect(s.ambient.x == 1e-40f, "a subnormal is a finite number: %g", s.ambient.x);
  scene_free(&s);
  scene_init(&s);
  cr_assert(parser_load_string("t.scene", "film 16384 1024\ncamera fov 179.9 focal 2\n", &s));
  cr_expect(s.width == 16384 && s.height == 1024 && s.camera.focal == 2.0f);
  scene_free(&s);
}

/* Parse `text` as t.scene, expect failure, return what it printed on stderr
 * (caller frees). */
static char *parse_error(const char *text)
{
  fflush(stderr);
  FILE *tmp = tmpfile();
  cr_assert(tmp);
  int saved = dup(2);
  dup2(fileno(tmp), 2);
  Scene s;
  scene_init(&s);
  bool ok = parser_load_string("t.scene", text, &s);
  fflush(stderr);
  dup2(saved, 2);
  close(saved);
  if (ok)
    scene_free(&s);
  cr_assert(!ok, "parsed without error:\n%s", text);
  cr_expect(s.n_instances == 0 && s.materials == NULL, "the scene was not freed");
  long n = ftell(tmp);
  char *buf = calloc((size_t)n + 1, 1);
  rewind(tmp);
  cr_assert(buf && fread(buf, 1, (size_t)n, tmp) == (size_t)n);
  fclose(tmp);
  return buf;
}

static void expect_error(const char *text, const char *message)
{
  char *got = parse_error(text);
  char want[512];
  snprintf(want, sizeof want, "%s\n", message);
  cr_expect(strcmp(got, want) == 0, "for:\n%s\nstderr: %sexpected: %s", text, got, want);
  free(got);
}

#define STATEMENTS "(film, camera, ambient, background, material, plane, sphere, " \
                   "light, samples, light_samples)"

Test(parser, unknown_statement_suggests_the_nearest)
{
  /* "sphre" is one edit from "sphere". */
  expect_error("sphre center 0 0 0 radius 1 material m\n",
               "t.scene:1:1: expected a statement " STATEMENTS ", found 'sphre'; did you "
               "mean 'sphere'?");
  /* Line and column count comments, blank lines and indentation. */
  expect_error("# comment\n\n  lihgt point position 0 0 0 power 1 1 1\n",
               "t.scene:3:3: expected a statement " STATEMENTS ", found 'lihgt'; did you "
               "mean 'light'?");
  /* Nothing near: no suggestion. */
  expect_error("teapot 1 2 3\n", "t.scene:1:1: expected a statement " STATEMENTS
                                 ", found 'teapot'");
}

Test(parser, unknown_keyword_suggests_the_nearest)
{
  /* s=1 center=8 0=15,17,19 radius=21 1=28 materal=30 */
  expect_error("sphere center 0 0 0 radius 1 materal m\n",
               "t.scene:1:30: expected a sphere keyword (center, radius, material), found "
               "'materal'; did you mean 'material'?");
  expect_error("camera eye 0 0 5 lookat 0 0 0\n",
               "t.scene:1:18: expected a camera keyword (eye, center, up, fov, focal), "
               "found 'lookat'");
  expect_error("light pointt position 0 0 0 power 1 1 1\n",
               "t.scene:1:7: expected a light type (point, directional, area), found "
               "'pointt'; did you mean 'point'?");
  expect_error("light point position 0 0 0 powr 1 1 1\n",
               "t.scene:1:28: expected a point light keyword (position, power, radius), "
               "found 'powr'; did you mean 'power'?");
}

Test(parser, missing_values)
{
  expect_error("sphere center 0 0 radius 1 material m\n",
               "t.scene:1:19: expected 3 numbers after 'center', found 'radius'");
  expect_error("sphere center 0 0 0 radius\n",
               "t.scene:1:27: expected a number after 'radius', found end of line");
  expect_error("sphere center 0 0 0 radius 1\n",
               "t.scene:1:29: expected 'material' in this sphere statement, found end of line");
  expect_error("film 800\n", "t.scene:1:9: expected the film height, found end of line");
  expect_error("ambient 0.1 0.1\n",
               "t.scene:1:16: expected 3 numbers >= 0 after 'ambient', found end of line");
  expect_error("light\n", "t.scene:1:6: expected a light type (point, directional, area), "
                          "found end of line");
  expect_error("material\n", "t.scene:1:9: expected a material name, found end of line");
}

Test(parser, extra_values)
{
  expect_error("sphere center 0 0 0 1 radius 1 material m\n",
               "t.scene:1:21: expected a sphere keyword, found an extra value '1'");
  expect_error("film 10 10 5\n", "t.scene:1:12: expected end of line, found an extra value '5'");
  expect_error("background 0 0 0 0\n",
               "t.scene:1:18: expected end of line, found an extra value '0'");
  expect_error("samples 4 4\n", "t.scene:1:11: expected end of line, found an extra value '4'");
}

Test(parser, non_finite_numbers)
{
  expect_error("sphere center 0 0 0 radius inf material m\n",
               "t.scene:1:28: expected a number after 'radius', found a non-finite value 'inf'");
  expect_error("sphere center 0 nan 0 radius 1 material m\n",
               "t.scene:1:17: expected 3 numbers after 'center', found a non-finite value 'nan'");
  expect_error("background 1e999 0 0\n",
               "t.scene:1:12: expected 3 numbers >= 0 after 'background', found a non-finite "
               "value '1e999'");
  expect_error("camera fov -INFINITY\n",
               "t.scene:1:12: expected a number after 'fov', found a non-finite value "
               "'-INFINITY'");
}

Test(parser, negative_colours)
{
  expect_error("ambient -0.1 0 0\n",
               "t.scene:1:9: expected 3 numbers >= 0 after 'ambient', found '-0.1'");
  expect_error("material m diffuse 0.5 -0.5 0.5\n",
               "t.scene:1:24: expected 3 numbers >= 0 after 'diffuse', found '-0.5'");
  expect_error("material m shininess -1\n",
               "t.scene:1:22: expected shininess >= 0, found '-1'");
}

Test(parser, radius_must_be_positive)
{
  expect_error("sphere center 0 0 0 radius 0 material m\n",
               "t.scene:1:28: expected a radius > 0, found '0'");
  expect_error("sphere center 0 1 0 radius -1 material red\n",
               "t.scene:1:28: expected a radius > 0, found '-1'");
  /* An underflow to zero is zero, said as written. */
  expect_error("sphere radius 1e-50 center 0 0 0 material m\n",
               "t.scene:1:15: expected a radius > 0, found '1e-50'");
  expect_error("light point position 0 0 0 power 1 1 1 radius 0\n",
               "t.scene:1:47: expected a radius > 0, found '0'");
}

Test(parser, zero_normal_edge_and_direction)
{
  /* plane=1 point=7 0=13,15,17 normal=19 0=26 */
  expect_error("plane point 0 0 0 normal 0 0 0 material m\n",
               "t.scene:1:26: expected a non-zero normal, found '0 0 0'");
  /* light=1 area=7 corner=12 0=19,21,23 edge1=25 0=31 */
  expect_error("light area corner 0 0 0 edge1 0 0 0 edge2 0 0 1 power 1 1 1\n",
               "t.scene:1:31: expected a non-zero edge1, found '0 0 0'");
  expect_error("light area corner 0 0 0 edge1 1 0 0 edge2 0 0 0 power 1 1 1\n",
               "t.scene:1:43: expected a non-zero edge2, found '0 0 0'");
  expect_error("light directional direction 0 0 0 irradiance 1 1 1\n",
               "t.scene:1:29: expected a non-zero direction, found '0 0 0'");
}

Test(parser, parallel_edges)
{
  expect_error("light area corner 0 0 0 edge1 1 0 0 edge2 -2 0 0 power 1 1 1\n",
               "t.scene:1:43: expected edge2 not parallel to edge1 (a light with an area), "
               "found parallel edges");
}

Test(parser, field_of_view_in_the_open_interval)
{
  expect_error("camera fov 0\n",
               "t.scene:1:12: expected a field of view in (0, 180) degrees, found '0'");
  expect_error("camera eye 0 0 5 fov 180\n",
               "t.scene:1:22: expected a field of view in (0, 180) degrees, found '180'");
  expect_error("camera focal 0\n", "t.scene:1:14: expected a focal distance > 0, found '0'");
}

Test(parser, eye_equal_to_center)
{
  /* camera=1 eye=8 1=12,14,16 center=18 1=25 */
  expect_error("camera eye 1 2 3 center 1 2 3\n",
               "t.scene:1:25: expected eye and center at different points, found both at "
               "(1 2 3)");
}

Test(parser, up_parallel_to_the_view)
{
  /* camera=1 eye=8 0=12,14,16 center=18 0=25 -5=27 0=30 up=32 0=35 */
  expect_error("camera eye 0 0 0 center 0 -5 0 up 0 1 0\n",
               "t.scene:1:35: expected an up vector not parallel to the view direction, "
               "found up (0 1 0)");
  expect_error("camera up 0 0 0\n", "t.scene:1:11: expected a non-zero up vector, found '0 0 0'");
}

Test(parser, undefined_material)
{
  /* sphere=1 center=8 0=15,17,19 radius=21 1=28 material=30 blu=39 */
  expect_error("material red diffuse 1 0 0\nsphere center 0 0 0 radius 1 material blu\n",
               "t.scene:2:39: expected a defined material name (red), found 'blu'");
  expect_error("sphere center 0 0 0 radius 1 material rde\nmaterial red diffuse 1 0 0\n",
               "t.scene:1:39: expected a defined material name (red), found 'rde'; did you "
               "mean 'red'?");
  expect_error("plane point 0 0 0 normal 0 1 0 material floor\n",
               "t.scene:1:41: expected a defined material name, found 'floor' (the file "
               "defines no material)");
}

Test(parser, duplicate_material)
{
  expect_error("material red diffuse 1 0 0\nmaterial red diffuse 0 1 0\n",
               "t.scene:2:10: expected a new material name, found 'red' (already defined)");
}

Test(parser, duplicate_keyword_and_statement)
{
  expect_error("film 10 10\nfilm 20 20\n",
               "t.scene:2:1: expected one 'film' statement, found a second (first at line 1)");
  expect_error("sphere radius 1 center 0 0 0 radius 2 material m\n",
               "t.scene:1:30: expected each sphere keyword once, found a second 'radius' "
               "(first at column 8)");
}

Test(parser, film_size_limits)
{
  expect_error("film 16385 10\n",
               "t.scene:1:6: expected the film width, a whole number from 1 to 16384, found "
               "'16385'");
  expect_error("film 10 0\n",
               "t.scene:1:9: expected the film height, a whole number from 1 to 16384, found '0'");
  expect_error("film 12.5 10\n",
               "t.scene:1:6: expected the film width, a whole number from 1 to 16384, found "
               "'12.5'");
  /* 16384 * 1025 = 16793600 > 2^24 = 16777216. */
  expect_error("film 16384 1025\n",
               "t.scene:1:6: expected at most 16777216 pixels, found 16384x1025");
}

Test(parser, sample_counts_in_range)
{
  expect_error("samples 0\n", "t.scene:1:9: expected the number of samples, a whole number "
                              "from 1 to 65536, found '0'");
  expect_error("samples 65537\n", "t.scene:1:9: expected the number of samples, a whole "
                                  "number from 1 to 65536, found '65537'");
  expect_error("light_samples 2.5\n", "t.scene:1:15: expected the number of light samples, "
                                      "a whole number from 1 to 65536, found '2.5'");
  expect_error("samples 1e9\n", "t.scene:1:9: expected the number of samples, a whole number "
                                "from 1 to 65536, found '1e9'");
}

Test(parser, bad_names_and_bytes)
{
  expect_error("material 9lives diffuse 1 1 1\n",
               "t.scene:1:10: expected a material name (letters, digits, '_', at most 63 "
               "characters), found '9lives'");
  expect_error("film 10 10\nfilm\x01 10 10\n",
               "t.scene:2:5: expected text, found the control byte 0x01");
}

Test(parser, missing_file)
{
  fflush(stderr);
  FILE *tmp = tmpfile();
  int saved = dup(2);
  dup2(fileno(tmp), 2);
  Scene s;
  scene_init(&s);
  bool ok = parser_load_file(BUILD_DIR "/no-such.scene", &s);
  fflush(stderr);
  dup2(saved, 2);
  close(saved);
  cr_expect(!ok);
  char buf[256] = "";
  rewind(tmp);
  cr_expect(fread(buf, 1, sizeof buf - 1, tmp) > 0);
  fclose(tmp);
  cr_expect(strcmp(buf, "parser: cannot read '" BUILD_DIR "/no-such.scene': No such file or "
                        "directory\n") == 0, "stderr: %s", buf);
}
