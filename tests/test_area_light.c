/* Unit tests of step 08's area lights (shade_area, shade_trace): the estimate
 * against Lambert's closed-form polygon irradiance (bias checked over many
 * seeds), a tiny light against a point light, one-sidedness, the
 * shadow-volume skip against the full estimate, and the radiance the camera
 * sees.
 * docs/08-area-lights.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "accel/accel.h"
#include "app/parser.h"
#include "rng.h"
#include "sampler.h"
#include "shade.h"

enum { ALL_FEATURES = SCENE_CAMERA | SCENE_LIGHTS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES |
                      SCENE_SAMPLES | SCENE_AREA_LIGHTS };

/* A white diffuse floor (y = 0, instance 0) under whatever `lights` says:
 * Phong then returns the irradiance E = sum L_i (n . l) itself. */
static void load(Scene *s, const char *lights)
{
  char text[1024];
  snprintf(text, sizeof text,
           "material white diffuse 1 1 1\n"
           "plane point 0 0 0 normal 0 1 0 material white\n%s\n", lights);
  scene_init(s);
  cr_assert(parser_load_string("test", text, s));
  cr_assert(scene_prepare(s, ALL_FEATURES));
}

/* The floor's hit at (x, 0, z), normal up. */
static Hit floor_hit(const Scene *s, float x, float z)
{
  Hit h = {.t = 1.0f, .p = vec_make(x, 0.0f, z), .n = vec_make(0.0f, 1.0f, 0.0f),
           .p_err = 1e-6f, .inst = &s->instances[0]};
  return h;
}

/* The red channel of Phong at `h` for seed, light samples, pattern, adaptive. */
static double estimate(const Scene *s, const Hit *h, uint32_t seed, int n, int kind,
                       float adaptive, uint64_t *rays)
{
  RenderSettings set = {.seed = seed, .samples = 1, .light_samples = n,
                        .sampler = kind, .adaptive = adaptive};
  RenderCtx ctx = {.set = &set, .pixel = 7, .sample = 0};
  vec3s c = shade_phong(s, h, vec_make(0.0f, 1.0f, 5.0f), &ctx);
  if (rays)
    *rays = ctx.rays;
  return c.x;
}

/* Lambert's formula in long double: irradiance at p (normal n) from a polygon
 * of radiance L with vertices v[0..3] (in order around it):
 *   E = (L/2) |sum_i Theta_i (n . Gamma_i)|,
 * Theta_i the angle between the directions to v_i and v_{i+1} seen from p,
 * Gamma_i the unit normal of the plane through p, v_i and v_{i+1}. */
static long double lambert(long double v[4][3], const long double p[3],
                           const long double n[3], long double L)
{
  long double sum = 0.0L;
  for (int i = 0; i < 4; i++) {
    const long double *v0 = v[i], *v1 = v[(i + 1) % 4];
    long double a[3], b[3], c[3];
    for (int k = 0; k < 3; k++) {
      a[k] = v0[k] - p[k];
      b[k] = v1[k] - p[k];
    }
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    long double cn = sqrtl(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    long double theta = atan2l(cn, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
    sum += theta * (n[0] * c[0] + n[1] * c[1] + n[2] * c[2]) / cn;
  }
  return 0.5L * L * fabsl(sum);
}

/* The vertices corner, +e1, +e1+e2, +e2 of a parallelogram, and its area. */
static long double quad_vertices(const long double c[3], const long double e1[3],
                                 const long double e2[3], long double v[4][3])
{
  for (int k = 0; k < 3; k++) {
    v[0][k] = c[k];
    v[1][k] = c[k] + e1[k];
    v[2][k] = c[k] + e1[k] + e2[k];
    v[3][k] = c[k] + e2[k];
  }
  long double x = e1[1] * e2[2] - e1[2] * e2[1], y = e1[2] * e2[0] - e1[0] * e2[2],
              z = e1[0] * e2[1] - e1[1] * e2[0];
  return sqrtl(x * x + y * y + z * z);
}

Test(area_light, lambert_reference_gives_pi_L_under_a_huge_light)
{
  /* A 2e4 x 2e4 square 1 above p fills the hemisphere: E -> pi L (the check
   * of the reference itself; the exact value is pi L (1 - O(1e-4))). */
  long double c[3] = {-1e4L, 1.0L, -1e4L}, e1[3] = {2e4L, 0, 0}, e2[3] = {0, 0, 2e4L};
  long double v[4][3], p[3] = {0, 0, 0}, n[3] = {0, 1, 0};
  quad_vertices(c, e1, e2, v);
  long double e = lambert(v, p, n, 1.0L);
  cr_expect(fabsl(e - 3.14159265358979323846L) < 1e-3L, "E = %.9Lf, expected pi", e);
}

/* Mean and standard error of the estimate over `seeds` seeds. */
static void seed_stats(const Scene *s, const Hit *h, int n, int kind, int seeds,
                       double *mean, double *se)
{
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < seeds; k++) {
    double e = estimate(s, h, 1000u + (uint32_t)k, n, kind, 0.0f, NULL);
    sum += e;
    sum2 += e * e;
  }
  *mean = sum / seeds;
  double var = (sum2 - sum * sum / seeds) / (seeds - 1);
  *se = sqrt(fmax(var, 0.0) / seeds);
}

Test(area_light, unoccluded_estimate_is_unbiased_against_lambert_formula)
{
  /* A tilted 2 x 1 light (facing down and toward +z), power 6: L = 6 / A. */
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0.4 1 power 6 6 6");
  long double c[3] = {-1, 3, -0.5L}, e1[3] = {2, 0, 0}, e2[3] = {0, 0.4L, 1};
  long double v[4][3], n[3] = {0, 1, 0};
  long double L = 6.0L / quad_vertices(c, e1, e2, v);
  const float pts[3][2] = {{0.0f, 0.0f}, {1.5f, 0.7f}, {-2.5f, -1.25f}};
  const int kinds[3] = {SAMPLER_JITTER, SAMPLER_RANDOM, SAMPLER_SOBOL};
  for (int q = 0; q < 3; q++)
    for (int kk = 0; kk < 3; kk++) {
      Hit h = floor_hit(&s, pts[q][0], pts[q][1]);
      long double p[3] = {pts[q][0], 0, pts[q][1]};
      double ref = (double)lambert(v, p, n, L), mean, se;
      seed_stats(&s, &h, 16, kinds[kk], 64, &mean, &se);
      /* 4 standard errors, plus float rounding of a 16-term sum. */
      cr_expect(fabs(mean - ref) <= 4.0 * se + 1e-5 * ref,
                "%s at (%g, %g): mean %.7f over 64 seeds, Lambert %.7f, se %.2g",
                sampler_name(kinds[kk]), pts[q][0], pts[q][1], mean, ref, se);
      cr_expect(se > 0.0, "the seeds must change the samples");
    }
  scene_free(&s);
}

Test(area_light, stratified_samples_vary_far_less_than_independent_ones)
{
  /* Smooth integrand: jittered strata give variance O(N^-2) against N^-1. */
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0 1 power 6 6 6");
  Hit h = floor_hit(&s, 0.8f, 0.3f);
  double m_j, se_j, m_r, se_r;
  seed_stats(&s, &h, 64, SAMPLER_JITTER, 64, &m_j, &se_j);
  seed_stats(&s, &h, 64, SAMPLER_RANDOM, 64, &m_r, &se_r);
  cr_expect(se_j < 0.25 * se_r, "jitter se %.3g, random se %.3g", se_j, se_r);
  scene_free(&s);
}

Test(area_light, regular_grid_converges_to_lambert_formula)
{
  /* Deterministic cell centres (the midpoint rule): error O(1/N) for N cells. */
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0 1 power 6 6 6");
  long double c[3] = {-1, 3, -0.5L}, e1[3] = {2, 0, 0}, e2[3] = {0, 0, 1};
  long double v[4][3], n[3] = {0, 1, 0}, p[3] = {0.5L, 0, -0.2L};
  long double L = 6.0L / quad_vertices(c, e1, e2, v);
  double ref = (double)lambert(v, p, n, L);
  Hit h = floor_hit(&s, 0.5f, -0.2f);
  double e = estimate(&s, &h, 1, 1024, SAMPLER_GRID, 0.0f, NULL);
  cr_expect(fabs(e - ref) < 1e-4 * ref, "grid 32 x 32: %.8f, Lambert %.8f", e, ref);
  scene_free(&s);
}

Test(area_light, tiny_light_is_a_point_light_with_cos_theta_light)
{
  /* A 1e-3 square facing straight down at (0.3, 2, -0.4), power 5: at p the
   * light is P cos(theta_light) cos(theta_p) / r^2 (computed in long double)
   * to within its size over the distance (~1e-3 relative), and equal to the
   * step's own point light of power P cos(theta_light). */
  Scene s, pt;
  load(&s, "light area corner 0.2995 2 -0.4005 edge1 0.001 0 0 edge2 0 0 0.001 "
           "power 5 5 5");
  const float pts[3][2] = {{0.3f, -0.4f}, {1.5f, 0.5f}, {-2.0f, 1.0f}};
  for (int q = 0; q < 3; q++) {
    long double d[3] = {0.3L - pts[q][0], 2.0L, -0.4L - pts[q][1]};
    long double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    long double cos_t = d[1] / sqrtl(r2); /* both cosines: light faces -y, floor +y */
    double ref = (double)(5.0L * cos_t * cos_t / r2);
    Hit h = floor_hit(&s, pts[q][0], pts[q][1]);
    double e = estimate(&s, &h, 3, 16, SAMPLER_JITTER, 0.0f, NULL);
    cr_expect(fabs(e - ref) < 1e-3 * ref, "at (%g, %g): %.7f, expected %.7f",
              pts[q][0], pts[q][1], e, ref);
    char light[128];
    snprintf(light, sizeof light, "light point position 0.3 2 -0.4 power %.9f %.9f %.9f",
             (double)(5.0L * cos_t), (double)(5.0L * cos_t), (double)(5.0L * cos_t));
    load(&pt, light);
    double e_pt = estimate(&pt, &h, 3, 1, SAMPLER_JITTER, 0.0f, NULL);
    cr_expect(fabs(e - e_pt) < 1e-3 * e_pt, "tiny area %.7f, point light %.7f", e, e_pt);
    scene_free(&pt);
  }
  scene_free(&s);
}

Test(area_light, point_behind_the_light_gets_nothing)
{
  /* The light faces down (edge1 x edge2 = -y); a ceiling above it, facing
   * down at the light's back, gets exactly zero and traces no shadow ray. */
  Scene s;
  load(&s, "light area corner -1 3 -1 edge1 2 0 0 edge2 0 0 2 power 6 6 6\n"
           "plane point 0 5 0 normal 0 -1 0 material white");
  Hit h = {.t = 1.0f, .p = vec_make(0.2f, 5.0f, 0.1f), .n = vec_make(0.0f, -1.0f, 0.0f),
           .p_err = 1e-6f, .inst = &s.instances[1]};
  cr_assert(s.instances[1].shape == SHAPE_PLANE);
  uint64_t rays;
  double e = estimate(&s, &h, 1, 16, SAMPLER_JITTER, 0.0f, &rays);
  cr_expect(e == 0.0 && rays == 0, "behind the light: %g with %llu rays", e,
            (unsigned long long)rays);
  /* The floor below, in front of the light, does receive light. */
  Hit f = floor_hit(&s, 0.2f, 0.1f);
  cr_expect(estimate(&s, &f, 1, 16, SAMPLER_JITTER, 0.0f, NULL) > 0.1);
  scene_free(&s);
}

Test(area_light, shadow_volume_skip_equals_the_full_estimate_when_nothing_is_in_the_way)
{
  /* Nothing between the floor and the light: shade_phong shades the samples
   * in a view of the scene with no occluders (no shadow ray at all), and must
   * give exactly what shade_area gives with every shadow ray traced. */
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0.4 1 power 6 6 6");
  Hit h = floor_hit(&s, 0.4f, -0.3f);
  for (int kind = SAMPLER_GRID; kind < SAMPLER_COUNT; kind++) {
    uint64_t rays;
    double skipped = estimate(&s, &h, 9, 16, kind, 0.0f, &rays);
    RenderSettings set = {.seed = 9, .samples = 1, .light_samples = 16, .sampler = kind};
    RenderCtx ctx = {.set = &set, .pixel = 7, .sample = 0};
    vec3s v = glms_vec3_normalize(glms_vec3_sub(vec_make(0.0f, 1.0f, 5.0f), h.p));
    double traced = shade_area(&s, 0, &h, v, &ctx).x;
    cr_expect(skipped == traced, "%s: skipped %.9g, traced %.9g", sampler_name(kind),
              skipped, traced);
    cr_expect(rays == 0 && ctx.rays == 16, "%s: rays %llu with the skip, %llu without",
              sampler_name(kind), (unsigned long long)rays, (unsigned long long)ctx.rays);
  }
  scene_free(&s);
}

/* A random ray from the spawned origin of h to a point of the light. */
static bool random_ray_occluded(const Scene *s, const Hit *h, const Quad *q, Rng *r)
{
  vec3s x = quad_point(q, rng_float(r), rng_float(r));
  vec3s to_x = glms_vec3_sub(x, h->p);
  float dist = glms_vec3_norm(to_x);
  vec3s l = glms_vec3_scale(to_x, 1.0f / dist);
  if (!(glms_vec3_dot(h->n, l) > 0.0f))
    return false;
  return scene_occluded(s, ray_spawn(h, l), ray_shadow_tmax(dist));
}

Test(area_light, shadow_volume_test_never_skips_a_ray_that_is_blocked)
{
  /* Random spheres over the floor; shading points on the floor and on the
   * spheres. Whenever accel_quad_unoccluded says no shadow ray is needed, 64
   * random shadow rays (scene_occluded, the ray code itself) must all pass.
   * It must also say so often enough to matter, and sometimes not. */
  Rng r = rng_make(7, 0, 0);
  int skipped = 0, kept = 0;
  for (int scene_k = 0; scene_k < 20; scene_k++) {
    char text[1024];
    int len = snprintf(text, sizeof text,
                       "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0.4 1 power 6 6 6\n");
    for (int k = 0; k < 4; k++)
      len += snprintf(text + len, sizeof text - (size_t)len,
                      "sphere center %g %g %g radius %g material white\n",
                      6.0f * rng_float(&r) - 3.0f, 2.5f * rng_float(&r),
                      6.0f * rng_float(&r) - 3.0f, 0.1f + 0.6f * rng_float(&r));
    Scene s;
    load(&s, text);
    if (scene_k % 2) /* half through the hierarchy's boxes, half the plain loop */
      cr_assert(accel_build(&s));
    const Quad *q = &s.lights[0].quad;
    for (int k = 0; k < 200; k++) {
      Hit h;
      Ray cam = {.o = vec_make(6.0f * rng_float(&r) - 3.0f, 5.0f, 6.0f * rng_float(&r) - 3.0f),
                 .d = glms_vec3_normalize(vec_make(rng_float(&r) - 0.5f, -1.0f,
                                                   rng_float(&r) - 0.5f))};
      if (!scene_intersect(&s, cam, INFINITY, &h) || h.inst->light >= 0)
        continue;
      if (!accel_quad_unoccluded(&s, &h, q)) {
        kept++;
        continue;
      }
      skipped++;
      for (int j = 0; j < 64; j++)
        cr_assert(!random_ray_occluded(&s, &h, q, &r), "a skipped shadow ray is blocked");
    }
    scene_free(&s);
  }
  cr_expect(skipped > 100 && kept > 100, "skipped %d, traced %d", skipped, kept);
}

Test(area_light, a_hidden_light_adds_nothing)
{
  /* A ceiling at y = 1.5 between the floor and the light hides all of it. */
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0.4 1 power 6 6 6\n"
           "plane point 0 1.5 0 normal 0 -1 0 material white");
  Hit h = floor_hit(&s, 0.4f, -0.3f);
  uint64_t rays;
  double full = estimate(&s, &h, 9, 16, SAMPLER_JITTER, 0.0f, &rays);
  cr_expect(full == 0.0, "E = %g, expected 0", full);
  cr_expect(rays == 16, "rays %llu, expected 16", (unsigned long long)rays);
  scene_free(&s);
}

Test(area_light, a_half_hidden_light_gives_a_penumbra)
{
  /* A sphere hides the light's left (-x) side from p = 0, not its right one
   * (checked by hand: the ray to (-1, 3, 0.5) passes 0.25 from the centre,
   * the ray to (1, 3, 0.5) 0.97). */
  Scene s, open;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0 1 power 6 6 6\n"
           "sphere center -0.5 1.5 0 radius 0.5 material white");
  load(&open, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0 1 power 6 6 6");
  Hit h = floor_hit(&s, 0.0f, 0.0f), ho = floor_hit(&open, 0.0f, 0.0f);
  double part = estimate(&s, &h, 5, 16, SAMPLER_JITTER, 0.0f, NULL);
  double lit = estimate(&open, &ho, 5, 16, SAMPLER_JITTER, 0.0f, NULL);
  cr_expect(part > 0.05 * lit && part < 0.95 * lit, "penumbra %g of %g", part, lit);
  scene_free(&s);
  scene_free(&open);
}

Test(area_light, camera_sees_P_over_A_on_the_front_face_and_black_behind)
{
  /* 2 x 2 light at y = 3 facing down, power (6, 4, 2): L = P / 4. */
  Scene s;
  load(&s, "light area corner -1 3 -1 edge1 2 0 0 edge2 0 0 2 power 6 4 2");
  RenderSettings set = {.seed = 1, .samples = 1, .light_samples = 4};
  RenderCtx ctx = {.set = &set};
  Ray up = {.o = vec_make(0.3f, 1.0f, 0.2f), .d = vec_make(0.0f, 1.0f, 0.0f)};
  vec3s c = shade_trace(&s, up, &ctx);
  cr_expect(c.x == 1.5f && c.y == 1.0f && c.z == 0.5f, "front: (%g, %g, %g)", c.x, c.y, c.z);
  Ray down = {.o = vec_make(0.3f, 6.0f, 0.2f), .d = vec_make(0.0f, -1.0f, 0.0f)};
  c = shade_trace(&s, down, &ctx);
  cr_expect(vec_is_zero(c), "back: (%g, %g, %g)", c.x, c.y, c.z);
  scene_free(&s);
}
