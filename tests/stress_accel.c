/* The acceleration structure (docs/performance.md) against the definition of
 * the queries: closest hit = the first instance, in order, at the smallest
 * sphere_hit_t / plane_hit_t distance; any-hit = some lit shape at t < tmax.
 * The reference is that loop written out here, over random scenes and rays
 * (grazing ones included), for the flat layout and the hierarchy. */
#include <omp.h>
#include <stdlib.h>

#include "accel/accel.h"
#include "check.h"
#include "rng.h"

static float uni(Rng *g, float lo, float hi) { return lo + (hi - lo) * rng_float(g); }

/* n random spheres (some coincident, some tiny) and a plane, prepared. */
static void random_scene(Scene *s, Rng *g, int n)
{
  scene_init(s);
  Material m = {.name = "m", .diffuse = vec_make(0.5f, 0.5f, 0.5f)};
  cr_assert(scene_add_material(s, &m), "out of memory");
  Instance pl = {.shape = SHAPE_PLANE, .plane = plane_make(vec_make(0, 0, 0), vec_make(0, 1, 0)),
                 .light = -1};
  cr_assert(scene_add_instance(s, &pl), "out of memory");
  for (int k = 0; k < n; k++) {
    Instance in = {.shape = SHAPE_SPHERE, .light = -1};
    in.sphere.center = vec_make(uni(g, -10, 10), uni(g, 0, 5), uni(g, -10, 10));
    in.sphere.radius = k % 7 == 0 ? 1e-3f : uni(g, 0.05f, 1.5f);
    if (k % 11 == 5) /* a duplicate of the previous sphere: equal distances */
      in.sphere = s->instances[s->n_instances - 1].sphere;
    cr_assert(scene_add_instance(s, &in), "out of memory");
  }
  cr_assert(scene_prepare(s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  cr_assert(accel_build(s), "accel_build (given code) failed");
}

static Ray random_ray(const Scene *s, Rng *g)
{
  Ray r = {.o = vec_make(uni(g, -12, 12), uni(g, 0.5f, 8), uni(g, -12, 12))};
  if (rng_float(g) < 0.3f) { /* aim at the rim of a sphere: grazing */
    const Sphere *sp = &s->instances[1 + (int)(rng_float(g) * (float)(s->n_instances - 1))].sphere;
    vec3s side = glms_vec3_normalize(vec_make(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1)));
    vec3s aim = glms_vec3_add(sp->center, glms_vec3_scale(side, sp->radius));
    r.d = glms_vec3_normalize(glms_vec3_sub(aim, r.o));
  } else {
    r.d = glms_vec3_normalize(vec_make(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1)));
  }
  return r;
}

static void check_layout(const char *layout, int n, int rays)
{
  setenv("RT_ACCEL", layout, 1);
  Rng g = rng_make(7, (uint32_t)n, 0);
  Scene s;
  random_scene(&s, &g, n);
  cr_assert(s.index, "accel_build (given code) built no index");
  Check c = CHECK("scene index (given code: common/accel/)",
                  "docs/performance.md, \"The scene queries (common/accel/accel.c, common/accel/bvh.c)\"");
  for (int k = 0; k < rays; k++) {
    Ray r = random_ray(&s, &g);
    float tmax = k % 3 ? INFINITY : uni(&g, 0.1f, 20);
    float best = tmax, got = tmax;
    int want = -1;
    for (int m = 0; m < s.n_instances; m++) {
      float t = scene_instance_hit_t(&s.instances[m], r, best);
      if (t < best) {
        best = t;
        want = m;
      }
    }
    const Instance *hit = s.index->closest(&s, &r, &got);
    CHECK_INT(&c, want, hit ? (int)(hit - s.instances) : -1, "%s layout, %d spheres, ray %d: "
              "the closest instance (-1: none), as the loop over scene_instance_hit_t says",
              layout, n, k);
    if (want >= 0)
      CHECK_NEAR(&c, best, got, 0.0, "%s layout, %d spheres, ray %d: the closest t", layout, n, k);
    CHECK_INT(&c, want >= 0, s.index->any(&s, &r, tmax), "%s layout, %d spheres, ray %d: any "
              "hit before tmax", layout, n, k);
  }
  CHECK_DONE(&c);
  scene_free(&s);
  unsetenv("RT_ACCEL");
}

Test(accel, flat_layout_gives_the_plain_loops_answers)
{
  for (int n = 1; n <= 40; n += 13)
    check_layout("flat", n, 20000);
}

Test(accel, hierarchy_gives_the_plain_loops_answers)
{
  for (int n = 1; n <= 3000; n = 3 * n + 7)
    check_layout("bvh", n, 20000);
}

/* Above 16384 spheres the hierarchy is built over Morton-ordered clusters
 * (common/accel/bvh.c), its sort split among the threads: the same answers
 * with one thread and with three. */
Test(accel, clustered_hierarchy_gives_the_plain_loops_answers)
{
  for (int threads = 1; threads <= 3; threads += 2) {
    omp_set_num_threads(threads);
    check_layout("bvh", 40000, 1500);
  }
}
