/* Unit tests of step 08's area lights (shade_area, shade_phong, shade_trace):
 * the estimate against Lambert's closed-form polygon irradiance (bias checked
 * over many seeds, through shade_area and shade_phong), a tiny light
 * against a point light, one-sidedness, light patterns keyed by the hit point
 * (also through the step's binary), and the radiance the camera sees. docs/08-area-lights.md. */
#include "check.h"
#include "area_light.h"
#include "counting.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "app/image.h"
#include "app/parser.h"
#include "rng.h"
#include "sampler.h"
#include "shade.h"

enum { ALL_FEATURES = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT |
                      SCENE_LIGHT_SHAPES | SCENE_SAMPLES | SCENE_AREA_LIGHTS };

/* A white diffuse floor (y = 0, instance 0) under whatever `lights` says:
 * Phong then returns the irradiance E = sum L_i (n . l) itself. */
static void load(Scene *s, const char *lights)
{
  char text[1024];
  snprintf(text, sizeof text,
           "material white diffuse 1 1 1\n"
           "plane point 0 0 0 normal 0 1 0 material white\n%s\n", lights);
  scene_init(s);
  cr_assert(parser_load_string("test", text, s) && scene_prepare(s, ALL_FEATURES),
            "cannot load the test scene:\n%s", text);
}

/* The floor's hit at (x, 0, z), normal up. */
static Hit floor_hit(const Scene *s, float x, float z)
{
  Hit h = {.t = 1.0f, .p = vec_make(x, 0.0f, z), .n = vec_make(0.0f, 1.0f, 0.0f),
           .p_err = 1e-6f, .material = s->instances[0].material,
           .light = s->instances[0].light, .inst = &s->instances[0]};
  return h;
}

#define DOC_LIGHT "docs/08-area-lights.md, \"The estimate: N point lights\""
#define DOC_KEYS "docs/08-area-lights.md, \"Where the samples go\""

/* The eye the tests shade toward. */
static const vec3s EYE = {.x = 0.0f, .y = 1.0f, .z = 5.0f};

/* `s` with n light samples of pattern `kind` keyed by `seed`. */
static Scene with(const Scene *s, uint32_t seed, int n, int kind)
{
  Scene w = *s;
  w.light_samples = n;
  w.sampler = (Sampler){.kind = (SamplerKind)kind, .seed = seed};
  return w;
}

/* The red channel of shade_phong at `h` for seed, light samples and
 * pattern; *rays (when not NULL): the queries it asked. */
static double estimate(const Scene *s, const Hit *h, uint32_t seed, int n, int kind,
                       uint64_t *rays)
{
  Scene w = with(s, seed, n, kind);
  CountingTable t;
  Scene c = counted(&w, &t);
  double e = shade_phong(&c, h, EYE).x;
  if (rays)
    *rays = (uint64_t)t.queries;
  return e;
}

/* The red channel of shade_area(light 0) itself with n samples; *rays (when
 * not NULL): the queries it asked. */
static double area(const Scene *s, const Hit *h, uint32_t seed, int n, int kind,
                   uint64_t *rays)
{
  Scene w = with(s, seed, n, kind);
  CountingTable t;
  Scene c = counted(&w, &t);
  vec3s v = glms_vec3_normalize(glms_vec3_sub(EYE, h->p));
  double e = shade_area(&c, 0, h, v).x;
  if (rays)
    *rays = (uint64_t)t.queries;
  return e;
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
  Check k = CHECK("lambert (the test's own reference)", DOC_LIGHT);
  CHECK_NEAR(&k, 3.14159265358979323846, (double)lambert(v, p, n, 1.0L), 1e-3,
             "irradiance under a square light filling the sky, radiance 1 (pi)");
}

/* Mean and standard error over `seeds` seeds of shade_phong (phong = true)
 * or of shade_area. */
static void seed_stats(const Scene *s, const Hit *h, int n, int kind, int seeds, bool phong,
                       double *mean, double *se)
{
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < seeds; k++) {
    uint32_t seed = 1000u + (uint32_t)k;
    double e = phong ? estimate(s, h, seed, n, kind, NULL) : area(s, h, seed, n, kind, NULL);
    sum += e;
    sum2 += e * e;
  }
  *mean = sum / seeds;
  double var = (sum2 - sum * sum / seeds) / (seeds - 1);
  *se = sqrt(fmax(var, 0.0) / seeds);
}

/* Every pattern that claims to be unbiased (random, jitter, Sobol), through
 * shade_area (16 samples) and through shade_phong (64 samples): the mean over 64 seeds lies within 4 standard errors (plus float
 * rounding of the sum) of Lambert's closed form. */
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
  Check k = CHECK("shade_area", DOC_LIGHT);
  for (int q = 0; q < 3; q++)
    for (int kk = 0; kk < 3; kk++)
      for (int phong = 0; phong < 2; phong++) {
        Hit h = floor_hit(&s, pts[q][0], pts[q][1]);
        long double p[3] = {pts[q][0], 0, pts[q][1]};
        double ref = (double)lambert(v, p, n, L), mean, se;
        int samples = phong ? 64 : 16;
        seed_stats(&s, &h, samples, kinds[kk], 64, phong, &mean, &se);
        const char *how = phong ? "shade_phong" : "shade_area";
        CHECK_NEAR(&k, ref, mean, 4.0 * se + 1e-5 * ref, "%s, %s, %d light samples, floor "
                   "point (%g, 0, %g) under a tilted light: mean over 64 seeds of the red "
                   "irradiance against Lambert's formula (4 standard errors)", how,
                   sampler_name(kinds[kk]), samples, pts[q][0], pts[q][1]);
        CHECK_THAT(&k, se > 0.0, "%s, %s: the estimate is the same for 64 seeds: the light "
                   "pattern must follow --seed", how, sampler_name(kinds[kk]));
      }
  CHECK_DONE(&k);
  scene_free(&s);
}

Test(area_light, stratified_samples_vary_far_less_than_independent_ones)
{
  /* Smooth integrand: jittered strata give variance O(N^-2) against N^-1. */
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0 1 power 6 6 6");
  Hit h = floor_hit(&s, 0.8f, 0.3f);
  double m_j, se_j, m_r, se_r;
  seed_stats(&s, &h, 64, SAMPLER_JITTER, 64, false, &m_j, &se_j);
  seed_stats(&s, &h, 64, SAMPLER_RANDOM, 64, false, &m_r, &se_r);
  Check k = CHECK("shade_area", DOC_KEYS);
  CHECK_THAT(&k, se_j < 0.25 * se_r, "64 light samples: jitter's standard error %.3g must be "
             "under a quarter of random's %.3g (one sample per stratum)", se_j, se_r);
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
  Check k = CHECK("shade_area", DOC_LIGHT);
  CHECK_REL(&k, ref, area(&s, &h, 1, 1024, SAMPLER_GRID, NULL), 1e-4,
            "grid 32 x 32 at floor point (0.5, 0, -0.2): red irradiance against Lambert's "
            "formula");
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
  Check k = CHECK("shade_area", DOC_LIGHT);
  for (int q = 0; q < 3; q++) {
    long double d[3] = {0.3L - pts[q][0], 2.0L, -0.4L - pts[q][1]};
    long double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    long double cos_t = d[1] / sqrtl(r2); /* both cosines: light faces -y, floor +y */
    double ref = (double)(5.0L * cos_t * cos_t / r2);
    Hit h = floor_hit(&s, pts[q][0], pts[q][1]);
    double e = area(&s, &h, 3, 16, SAMPLER_JITTER, NULL);
    CHECK_REL(&k, ref, e, 1e-3, "a 1 mm light, power 5, 2 above the floor, at floor point "
              "(%g, 0, %g): red, against P cos(theta_light) cos(theta_p) / r^2", pts[q][0],
              pts[q][1]);
    char light[128];
    snprintf(light, sizeof light, "light point position 0.3 2 -0.4 power %.9f %.9f %.9f",
             (double)(5.0L * cos_t), (double)(5.0L * cos_t), (double)(5.0L * cos_t));
    load(&pt, light);
    CHECK_REL(&k, estimate(&pt, &h, 3, 1, SAMPLER_JITTER, NULL), e, 1e-3,
              "the same point: the 1 mm area light against a point light of power "
              "P cos(theta_light) there");
    scene_free(&pt);
  }
  CHECK_DONE(&k);
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
           .p_err = 1e-6f, .material = s.instances[1].material,
           .light = s.instances[1].light, .inst = &s.instances[1]};
  cr_assert(s.instances[1].shape == SHAPE_PLANE);
  uint64_t rays;
  Check k = CHECK("shade_area", DOC_LIGHT);
  CHECK_NEAR(&k, 0.0, area(&s, &h, 1, 16, SAMPLER_JITTER, &rays), 0.0,
             "a ceiling point behind a one-sided light (it faces down, away): red");
  CHECK_INT(&k, 0, rays, "the same point: shadow rays traced (a sample that adds nothing "
            "needs none)");
  /* The floor below, in front of the light, does receive light. */
  Hit f = floor_hit(&s, 0.2f, 0.1f);
  double lit = area(&s, &f, 1, 16, SAMPLER_JITTER, NULL);
  CHECK_THAT(&k, lit > 0.1, "the floor point under the same light: red %g, expected more "
             "than 0.1", lit);
  scene_free(&s);
}

Test(area_light, a_hidden_light_adds_nothing)
{
  /* A ceiling at y = 1.5 between the floor and the light hides all of it. */
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0.4 1 power 6 6 6\n"
           "plane point 0 1.5 0 normal 0 -1 0 material white");
  Hit h = floor_hit(&s, 0.4f, -0.3f);
  uint64_t rays;
  Check k = CHECK("shade_area", DOC_LIGHT);
  CHECK_NEAR(&k, 0.0, estimate(&s, &h, 9, 16, SAMPLER_JITTER, &rays), 0.0,
             "a floor point under a ceiling that hides the light: red");
  CHECK_INT(&k, 16, rays, "the same point, 16 light samples: shadow rays (one each)");
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
  double part = area(&s, &h, 5, 16, SAMPLER_JITTER, NULL);
  double lit = area(&open, &ho, 5, 16, SAMPLER_JITTER, NULL);
  Check k = CHECK("shade_area", DOC_LIGHT);
  CHECK_THAT(&k, part > 0.05 * lit && part < 0.95 * lit, "a floor point whose light a sphere "
             "half hides: red %g, expected between 5%% and 95%% of the unshadowed %g", part, lit);
  scene_free(&s);
  scene_free(&open);
}

/* The light pattern of one camera sample: shade_area with one random light
 * sample at an unshadowed point, where the red value moves with the
 * sample's place on the light. Points a few float steps apart (the hit
 * points of different camera samples) each draw a pattern of their own; the
 * same point, the same pattern. */
Test(area_light, light_samples_are_keyed_by_the_hit_point)
{
  Scene s;
  load(&s, "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0.4 1 power 6 6 6");
  Hit h = floor_hit(&s, 0.4f, -0.3f);
  Check k = CHECK("shade_area (sampler_pattern_at)", DOC_KEYS);
  for (int kind = SAMPLER_RANDOM; kind < SAMPLER_COUNT; kind++) {
    double first = area(&s, &h, 9, 1, kind, NULL);
    int same_point = 0;
    for (int q = 1; q < 16; q++) {
      Hit moved = h;
      moved.p.x = nextafterf(h.p.x + (float)q * 1e-6f, INFINITY);
      same_point += fabs(area(&s, &moved, 9, 1, kind, NULL) - first) <= 1e-4 * first;
    }
    CHECK_INT(&k, 0, same_point, "%s, 1 light sample: points 1e-6 .. 1.5e-5 away that put "
              "their light sample where the first point does (each hit point draws its own "
              "pattern)", sampler_name((SamplerKind)kind));
    CHECK_NEAR(&k, first, area(&s, &h, 9, 1, kind, NULL), 0.0, "%s, the same point twice",
               sampler_name((SamplerKind)kind));
  }
  CHECK_DONE(&k);
  scene_free(&s);
}

/* Through the step's binary: a 1 x 1 film, 1 degree wide, looking straight
 * down at the floor point under a light that a sphere half hides (the scene
 * of a_half_hidden_light_gives_a_penumbra, the camera above the floor at
 * y = 1, below the sphere). With 64 camera samples and 1 light sample each,
 * the pixel averages 64 light samples, between 10% and 90% of the unshadowed
 * value, when each camera sample has its own (keyed by its hit point); one
 * shared light sample makes it all or nothing. */
Test(area_light, each_camera_sample_takes_its_own_light_samples)
{
  const char *base = "film 1 1\n"
                     "camera eye 0 1 0 center 0 0 0 up 0 0 -1 fov 1\n"
                     "material white diffuse 1 1 1\n"
                     "plane point 0 0 0 normal 0 1 0 material white\n"
                     "light area corner -1 3 -0.5 edge1 2 0 0 edge2 0 0 1 power 6 6 6\n";
  char text[2][512], path[2][256], out[256], cmd[1024];
  snprintf(text[0], sizeof text[0], "%s", base);
  snprintf(text[1], sizeof text[1], "%ssphere center -0.5 1.5 0 radius 0.5 material white\n",
           base);
  mkdir(BUILD_DIR "/test-out", 0755);
  double red[2][3];
  for (int v = 0; v < 2; v++) {
    snprintf(path[v], sizeof path[v], BUILD_DIR "/test-out/keys-%d.scene", v);
    FILE *f = fopen(path[v], "w");
    cr_assert(f && fputs(text[v], f) >= 0 && fclose(f) == 0, "cannot write %s", path[v]);
    for (int seed = 1; seed <= 3; seed++) {
      snprintf(out, sizeof out, BUILD_DIR "/test-out/keys-%d-%d.pfm", v, seed);
      snprintf(cmd, sizeof cmd, BUILD_DIR "/bin/" STEP_NAME " --scene %s --samples 64 "
               "--light-samples 1 --sampler random --adaptive 0 --seed %d --quiet -o %s",
               path[v], seed, out);
      cr_assert(system(cmd) == 0, "'%s' failed", cmd);
      int w, h;
      float *rgb;
      cr_assert(image_load(out, &w, &h, &rgb), "cannot read %s", out);
      red[v][seed - 1] = rgb[0];
      free(rgb);
    }
  }
  Check k = CHECK("shade_area (sampler_pattern_at)", DOC_KEYS);
  for (int seed = 0; seed < 3; seed++) {
    double frac = red[1][seed] / red[0][seed];
    CHECK_THAT(&k, frac > 0.1 && frac < 0.9, "a pixel on a penumbra, 64 camera samples of 1 "
               "light sample each, seed %d: %.3f of the unshadowed red, expected between 0.1 "
               "and 0.9 (64 light samples in all; 0 or 1 means every camera sample reused one "
               "light sample)", seed + 1, frac);
  }
}

Test(area_light, camera_sees_P_over_A_on_the_front_face_and_black_behind)
{
  /* 2 x 2 light at y = 3 facing down, power (6, 4, 2): L = P / 4. */
  Scene s;
  load(&s, "light area corner -1 3 -1 edge1 2 0 0 edge2 0 0 2 power 6 4 2");
  s.light_samples = 4;
  Check k = CHECK("shade_trace", "docs/08-area-lights.md, \"The light\"");
  Ray up = {.o = vec_make(0.3f, 1.0f, 0.2f), .d = vec_make(0.0f, 1.0f, 0.0f)};
  CHECK_VEC(&k, vec_make(1.5f, 1.0f, 0.5f), shade_trace(&s, up), 0.0,
            "a ray up into the front of a 2 x 2 light of power (6, 4, 2): P / A");
  Ray down = {.o = vec_make(0.3f, 6.0f, 0.2f), .d = vec_make(0.0f, -1.0f, 0.0f)};
  CHECK_VEC(&k, glms_vec3_zero(), shade_trace(&s, down), 0.0,
            "a ray down onto the back of the same light (one-sided): black");
  scene_free(&s);
}
