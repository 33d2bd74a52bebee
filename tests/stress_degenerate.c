/* Stress test 5 of docs/accuracy.md: degenerate inputs give no NaN and no
 * infinite pixel (rays parallel to planes, origins on surfaces, lights on
 * surfaces or at the shaded point, extreme shininess, zero-area lights). */
#include "check.h"

#include <criterion/redirect.h>
#include <stdlib.h>

#include "app/image.h"
#include "app/parser.h"
#include "shapes.h"
#include "stress.h"

#define STEP05 BUILD_DIR "/bin/05-shadows"

/* Render scene text with step 05; the number of non-finite channels. */
static long nonfinite_pixels(const char *name, const char *text)
{
  char scene[256], out[256], cmd[700];
  snprintf(scene, sizeof scene, STRESS_DIR "/t5_%s.scene", name);
  snprintf(out, sizeof out, STRESS_DIR "/t5_%s.pfm", name);
  FILE *f = fopen(scene, "w");
  cr_assert(f, "cannot write %s", scene);
  fputs(text, f);
  fclose(f);
  snprintf(cmd, sizeof cmd, STEP05 " --scene %s -o %s --threads 2 --quiet", scene, out);
  cr_assert(system(cmd) == 0, "the step's program failed (a crash or an error in a step's "
            "function; run the command to see): %s", cmd);
  int w, h;
  float *rgb;
  cr_assert(image_load(out, &w, &h, &rgb), "cannot read %s", out);
  long bad = 0;
  for (long k = 0; k < 3L * w * h; k++)
    bad += !isfinite(rgb[k]);
  free(rgb);
  return bad;
}

#define BASE                                                                  \
  "film 81 61\n"                                                              \
  "camera eye 0 2 6 center 0 0 0 up 0 1 0 fov 40\n"                           \
  "material m diffuse 0.7 0.7 0.7 specular 0.5 0.5 0.5 shininess %s\n"        \
  "plane point 0 0 0 normal 0 1 0 material m\n"                               \
  "sphere center 0 1 0 radius 1 material m\n"

Test(stress, t5_degenerate_scenes_render_no_nan_or_infinite_pixel)
{
  stress_step(5);
  /* Each case, and where a NaN or an infinity would come from. */
  struct {
    const char *name, *shininess, *light, *fn, *why;
  } cases[] = {
      {"light_on_sphere", "32", "light point position 0 2 0 power 10 10 10\n",
       "light_incident (step 04)",
       "a point light on the surface: r = 0 at the shaded point gives P / 0 and l = 0 / 0 "
       "unless r <= min_dist gives zero"},
      {"light_on_plane", "32", "light point position 1.5 0 0 power 10 10 10\n",
       "light_incident (step 04)",
       "a point light in the floor: r = 0 where it touches"},
      {"light_at_shaded_point", "32", "light point position 0 0 0 power 10 10 10\n",
       "light_incident (step 04)", "a point light exactly at a shaded point: r = 0"},
      {"light_inside_sphere", "32", "light point position 0 1 0 power 10 10 10\n",
       "shade_visible, ray_spawn (step 05)", "a light inside a sphere: every shadow ray is blocked"},
      {"shininess_0", "0", "light point position 3 4 3 power 10 10 10\n",
       "shade_phong_light (step 04)",
       "shininess 0: max(0, r.v)^0 is 1, also for r.v = 0"},
      {"shininess_1e9", "1e9", "light point position 3 4 3 power 10 10 10\n",
       "shade_phong_light (step 04)", "shininess 1e9: the lobe underflows to 0"},
      {"grazing_light", "32", "light directional direction 1 0 0 irradiance 1 1 1\n",
       "shade_phong_light (step 04)", "a light in the floor's plane: n.l = 0 adds nothing"},
  };
  stress_table("t5_degenerate", "Test 5: non-finite channels in step 05 renders of "
               "degenerate scenes (81x61)", "| scene | non-finite channels |\n|---|---|");
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    char text[1024];
    snprintf(text, sizeof text, BASE "%s", cases[k].shininess, cases[k].light);
    long bad = nonfinite_pixels(cases[k].name, text);
    stress_row("t5_degenerate", "| %s | %ld |", cases[k].name, bad);
    Check c = CHECK(cases[k].fn, "docs/accuracy.md, \"What the code does, and why\"");
    CHECK_INT(&c, 0, bad, "step 05's render of a degenerate scene, %s (%s): channels that are "
              "NaN or infinite", cases[k].name, cases[k].why);
  }
}

Test(stress, t5_degenerate_rays_and_zero_area_lights_give_no_nan)
{
  stress_step(5);
  /* A ray parallel to a plane, above it and inside it: no hit. */
  Plane pl = plane_make(vec_make(0.0f, 1.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  Ray above = {.o = vec_make(0.0f, 2.0f, 0.0f), .d = vec_make(1.0f, 0.0f, 0.0f)};
  Ray inside = {.o = vec_make(0.0f, 1.0f, 0.0f), .d = vec_make(1.0f, 0.0f, 0.0f)};
  Check pc = CHECK("plane_hit_t (step 02)", "docs/02-intersection.md, \"What you write\"");
  CHECK_NEAR(&pc, INFINITY, plane_hit_t(&pl, above, INFINITY), 0.0,
             "ray parallel to the plane, above it: a miss is INFINITY");
  CHECK_NEAR(&pc, INFINITY, plane_hit_t(&pl, inside, INFINITY), 0.0,
             "ray inside the plane (0 / 0): a miss is INFINITY, never NaN");
  /* Origins exactly on spheres (float points on the surface): any answer
   * must be finite or INFINITY, and a filled hit finite. */
  long bad = 0;
  Check st = CHECK("sphere_hit_t (step 02)", "docs/02-intersection.md, \"What you write\"");
  Check sf = CHECK("sphere_hit_fill (step 02)", "docs/02-intersection.md, \"What you write\"");
  Check sp = CHECK("ray_spawn (step 05)", "docs/05-shadows.md, \"What you write\"");
  for (int k = 0; k < 20000; k++) {
    Rng g = rng_make(5, 0, (uint32_t)k);
    Sphere s = {.center = glms_vec3_scale(stress_unit(&g), (float)stress_log10u(&g, -3, 5)),
                .radius = (float)stress_log10u(&g, -3, 3)};
    vec3s n = stress_unit(&g);
    Ray r = {.o = glms_vec3_add(s.center, glms_vec3_scale(n, s.radius)), .d = stress_unit(&g)};
    float t = sphere_hit_t(&s, r, INFINITY);
    bad += isnan(t);
    CHECK_THAT(&st, !isnan(t), "ray %d from a point on a sphere (radius %.3g): t is NaN", k,
               s.radius);
    if (t < INFINITY) {
      Hit hit;
      sphere_hit_fill(&s, r, t, &hit);
      bool ok = vec_is_finite(hit.p) && vec_is_finite(hit.n) && isfinite(hit.p_err);
      bad += !ok;
      CHECK_THAT(&sf, ok, "ray %d from a point on a sphere, t = %.9g: p, n or p_err not finite "
                 "(p = (%g, %g, %g), n = (%g, %g, %g), p_err = %g)", k, t, hit.p.x, hit.p.y,
                 hit.p.z, hit.n.x, hit.n.y, hit.n.z, hit.p_err);
      Ray sh = ray_spawn(&hit, r.d);
      bad += !vec_is_finite(sh.o);
      CHECK_THAT(&sp, !ok || vec_is_finite(sh.o), "ray %d: the spawned origin is not finite", k);
    }
  }
  CHECK_DONE(&st);
  CHECK_DONE(&sf);
  CHECK_DONE(&sp);
  /* A zero-area light: the parser rejects it; built in code, it is never hit. */
  Scene sc;
  scene_init(&sc);
  Check g = CHECK("parser_load_string, quad_hit_t (given code)",
                  "docs/08-area-lights.md, \"The light\"");
  cr_redirect_stderr();
  CHECK_INT(&g, 0, parser_load_string("zero.scene", "light area corner 0 0 0 edge1 1 0 0 "
                                      "edge2 2 0 0 power 1 1 1\n", &sc),
            "a zero-area light in a scene file: accepted");
  scene_free(&sc);
  Quad q = quad_make(vec_make(0.0f, 0.0f, 0.0f), vec_make(1.0f, 0.0f, 0.0f), vec_make(2.0f, 0.0f, 0.0f));
  Ray down = {.o = vec_make(0.5f, 1.0f, 0.0f), .d = vec_make(0.0f, -1.0f, 0.0f)};
  CHECK_THAT(&g, q.area == 0.0f && quad_hit_t(&q, down, INFINITY) == INFINITY,
             "a zero-area quad: area %g, and a ray into it must miss", q.area);
  CHECK_THAT(&g, vec_is_finite(quad_point(&q, 0.5f, 0.5f)), "a zero-area quad's point (0.5, "
             "0.5) is not finite");
  stress_table("t5_rays", "Test 5b: degenerate rays", "| check | NaN or infinite results |\n|---|---|");
  stress_row("t5_rays", "| 20000 origins on spheres (t, p, n, p_err, spawned origin) | %ld |", bad);
}
