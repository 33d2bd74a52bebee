/* Unit tests of the lights' incident radiance (step 04): point light
 * L_i = P / r^2, directional light L_i = E from -direction.
 * docs/04-phong.md, "What you write". */
#include "check.h"

#include <stdlib.h>
#include <sys/stat.h>

#include "app/image.h"
#include "light.h"

#define DOC "docs/04-phong.md, \"What you write\""

/* P / r^2 may be computed as P * (1 / r^2) or from r = sqrt(r^2): a few
 * roundings, so 4 ulps. */
enum { LI_ULPS = 4 };

static void check_ulps3(Check *c, const long double want[3], vec3s got, int ulps, const char *what)
{
  static const char *const names[3] = {"x / red", "y / green", "z / blue"};
  for (int k = 0; k < 3; k++)
    CHECK_ULPS(c, (float)want[k], got.raw[k], ulps, "%s, %s", what, names[k]);
}

Test(light, point_light_falls_off_as_inverse_square)
{
  /* Light 4 units above along +z: L_i = (16, 32, 48) / 16, l = +z. */
  Light L = {.type = LIGHT_POINT, .position = vec_make(1, 2, 3), .power = vec_make(16, 32, 48)};
  vec3s l;
  float dist;
  vec3s li = light_incident(&L, vec_make(1, 2, -1), 0.0f, &l, &dist);
  Check c = CHECK("light_incident", DOC);
  const char *what = "point light of power (16, 32, 48) 4 units along +z";
  check_ulps3(&c, (long double[3]){1, 2, 3}, li, LI_ULPS,
              "point light (16, 32, 48) 4 units along +z: L_i = P / r^2");
  CHECK_VEC(&c, vec_make(0, 0, 1), l, 0.0, "%s: l, the unit direction toward it", what);
  CHECK_NEAR(&c, 4.0, dist, 0.0, "%s: its distance", what);
}

Test(light, point_light_off_axis)
{
  /* From the origin to (1, 2, 2): r = 3, L_i = P / 9, l = (1, 2, 2) / 3. */
  Light L = {.type = LIGHT_POINT, .position = vec_make(1, 2, 2), .power = vec_make(9, 4.5f, 1)};
  vec3s l;
  float dist;
  vec3s li = light_incident(&L, vec_make(0, 0, 0), 1e-6f, &l, &dist);
  Check c = CHECK("light_incident", DOC);
  check_ulps3(&c, (long double[3]){1.0L, 0.5L, 1.0L / 9.0L}, li, LI_ULPS,
              "point light (9, 4.5, 1) at distance 3: L_i = P / 9");
  check_ulps3(&c, (long double[3]){1.0L / 3, 2.0L / 3, 2.0L / 3}, l, LI_ULPS,
              "the same light: l = (1, 2, 2) / 3");
  CHECK_ULPS(&c, 3.0f, dist, 2, "the same light: its distance");
  /* Twice as far: a quarter of the radiance. */
  li = light_incident(&L, vec_make(-1, -2, -2), 0.0f, &l, &dist);
  check_ulps3(&c, (long double[3]){0.25L, 0.125L, 1.0L / 36.0L}, li, LI_ULPS,
              "the same light from twice as far (distance 6): L_i = P / 36");
  CHECK_ULPS(&c, 6.0f, dist, 2, "from twice as far: the distance");
}

Test(light, directional_light_is_constant)
{
  /* direction (1, -2, 2)/3 (the parser stores it unit): l = (-1, 2, -2)/3. */
  Light L = {.type = LIGHT_DIRECTIONAL, .direction = vec_make(1.0f / 3, -2.0f / 3, 2.0f / 3),
             .irradiance = vec_make(0.3f, 0.2f, 0.1f)};
  vec3s l;
  float dist;
  vec3s points[3] = {vec_make(0, 0, 0), vec_make(100, -50, 7), vec_make(-1e4f, 3, 1e4f)};
  Check c = CHECK("light_incident", DOC);
  for (int k = 0; k < 3; k++) {
    vec3s li = light_incident(&L, points[k], 0.0f, &l, &dist);
    CHECK_VEC(&c, L.irradiance, li, 0.0, "directional light, point %d: L_i = E", k);
    CHECK_VEC(&c, vec_make(-1.0f / 3, 2.0f / 3, -2.0f / 3), l, 1e-7,
              "directional light travelling along (1, -2, 2)/3, point %d: l = -direction", k);
    CHECK_NEAR(&c, INFINITY, dist, 0.0, "directional light, point %d: its distance", k);
  }
  CHECK_DONE(&c);
}

Test(light, point_light_at_the_shaded_point_gives_zero)
{
  Light L = {.type = LIGHT_POINT, .position = vec_make(1, 1, 1), .power = vec_make(1, 1, 1)};
  vec3s l;
  float dist;
  Check c = CHECK("light_incident", DOC);
  vec3s li = light_incident(&L, vec_make(1, 1, 1), 0.0f, &l, &dist);
  CHECK_VEC(&c, vec_make(0, 0, 0), li, 0.0, "point light at the shaded point itself: L_i");
  CHECK_THAT(&c, vec_is_finite(l), "the same: l must be finite (no 0/0), got (%g, %g, %g)",
             l.x, l.y, l.z);
  /* Closer than the point's error bound (min_dist): also zero, no 1/r^2 blow-up. */
  li = light_incident(&L, vec_make(1, 1, 1 + 1e-7f), 1e-6f, &l, &dist);
  CHECK_VEC(&c, vec_make(0, 0, 0), li, 0.0, "point light 1e-7 away, closer than "
            "min_dist = 1e-6: L_i");
  CHECK_THAT(&c, vec_is_finite(l), "the same: l must be finite, got (%g, %g, %g)", l.x, l.y,
             l.z);
}

/* Step 04's render (64 x 48, .pfm) of a sphere over a floor lit by one
 * directional light travelling along `dir`; the pixels, the caller frees. */
static float *directional_render(const char *tag, const char *dir)
{
  char scene[256], out[256], cmd[768];
  snprintf(scene, sizeof scene, BUILD_DIR "/test-out/dir-%s.scene", tag);
  snprintf(out, sizeof out, BUILD_DIR "/test-out/dir-%s.pfm", tag);
  mkdir(BUILD_DIR "/test-out", 0755);
  FILE *f = fopen(scene, "w");
  cr_assert(f && fprintf(f, "film 64 48\ncamera eye 0 2.2 9 center 0 0.8 0 up 0 1 0 fov 40\n"
                            "material m diffuse 0.8 0.6 0.4 specular 0.5 0.5 0.5 shininess 32\n"
                            "plane point 0 0 0 normal 0 1 0 material m\n"
                            "sphere center 0 1 0 radius 1 material m\n"
                            "light directional direction %s irradiance 1 1 1\n", dir) > 0 &&
                fclose(f) == 0, "cannot write %s", scene);
  remove(out);
  snprintf(cmd, sizeof cmd, BUILD_DIR "/bin/" STEP_NAME " --scene %s --threads 2 --quiet -o %s",
           scene, out);
  cr_assert(system(cmd) == 0, "'%s' failed", cmd);
  int w, h;
  float *rgb;
  cr_assert(image_load(out, &w, &h, &rgb) && w == 64 && h == 48, "cannot read %s", out);
  return rgb;
}

/* The scene format accepts directions of length 1e-18 to 1e18 and normalizes
 * them (docs/scene-format.md, "Limits"): a light travelling along
 * (0, -1e-8, -0.5e-8) lights the scene as one along (0, -1, -0.5). cglm 0.9's
 * own normalize makes the short one (0, 0, 0): a picture without its light. */
Test(light, a_directional_light_of_length_1e_8_lights_as_its_unit_twin)
{
  Check c = CHECK_RELYING("vec_normalize (the scene reader's light direction)",
                          "docs/accuracy.md, \"What the code does, and why\"",
                          "light_incident, shade_phong_light, shade_phong (step 04)");
  float *unit = directional_render("unit", "0 -1 -0.5");
  float *tiny = directional_render("1e-8", "0 -1e-8 -0.5e-8");
  double worst = 0.0, lit = 0.0;
  for (int k = 0; k < 64 * 48 * 3; k++) {
    worst = fmax(worst, fabs((double)tiny[k] - unit[k]));
    lit = fmax(lit, unit[k]);
  }
  CHECK_REQUIRE(&c, lit > 0.1, "the direction (0, -1, -0.5) lights nothing: brightest "
                "channel %.9g (expected the lit sphere and floor, above 0.1)", lit);
  /* The two unit vectors may differ in their last bit: a channel moves by a
   * few 1e-8. Without the light, the lit pixels lose all of it. */
  CHECK_NEAR(&c, 0.0, worst, 1e-6, "direction (0, -1e-8, -0.5e-8) against (0, -1, -0.5): "
             "the largest difference of a channel (" BUILD_DIR "/test-out/dir-1e-8.pfm "
             "against dir-unit.pfm)");
  free(unit);
  free(tiny);
}
