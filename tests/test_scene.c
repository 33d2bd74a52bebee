/* Unit tests of the scene queries (step 02, any-hit from step 05): closest
 * hit among overlapping objects, any-hit with tmax, lights' shapes never
 * occlude. docs/02-intersection.md, docs/05-shadows.md. */
#include "check.h"

#include "scene.h"
#include "shapes.h"

/* scene_intersect and scene_occluded are given code: they call the shapes'
 * functions, so a failure here is a failure of those. */
#define SHAPES "sphere_hit_t, sphere_hit_fill, plane_hit_t, plane_hit_fill (through scene_intersect)"
#define SPHERES "sphere_hit_t, sphere_hit_fill (through scene_intersect)"
#define DOC "docs/02-intersection.md, \"What you write\""

static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz)
{
  Ray r = {.o = vec_make(ox, oy, oz), .d = glms_vec3_normalize(vec_make(dx, dy, dz))};
  return r;
}

static void add_sphere(Scene *s, float x, float y, float z, float radius, int material)
{
  Instance inst = {.shape = SHAPE_SPHERE, .material = material, .light = -1,
                   .sphere = {.center = vec_make(x, y, z), .radius = radius}};
  cr_assert(scene_add_instance(s, &inst), "scene_add_instance failed (out of memory)");
}

/* Two materials, the floor y = 0 (material 0) and three overlapping spheres
 * along -z (material 1): radius 2 at z = -10, radius 1 at z = -9 (inside the
 * first, its front at z = -8), radius 3 at z = -12. */
static void build(Scene *s)
{
  scene_init(s);
  Material m0 = {.name = "floor"}, m1 = {.name = "ball"};
  cr_assert(scene_add_material(s, &m0) && scene_add_material(s, &m1), "out of memory");
  Plane ground = plane_make(vec_make(0, 0, 0), vec_make(0, 1, 0));
  Instance floor = {.shape = SHAPE_PLANE, .material = 0, .light = -1,
                    .plane = ground};
  cr_assert(scene_add_instance(s, &floor), "out of memory");
  add_sphere(s, 0, 1, -10, 2, 1);
  add_sphere(s, 0, 1, -9, 1, 1);
  add_sphere(s, 0, 1, -12, 3, 1);
}

Test(scene, closest_hit_among_overlapping_spheres)
{
  Scene s;
  build(&s);
  cr_assert(scene_prepare(&s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  /* From (0, 1, 0) along -z: fronts at z = -8 (r 2), -8 (r 1), -9 (r 3):
   * t = 8 (the first two touch there); the r 3 sphere's front is farther. */
  Hit h;
  Check c = CHECK(SPHERES, DOC);
  CHECK_REQUIRE(&c, scene_intersect(&s, ray(0, 1, 0, 0, 0, -1), INFINITY, &h),
                "ray from (0, 1, 0) along -z into three overlapping spheres: no hit found");
  CHECK_NEAR(&c, 8.0, h.t, 0.0, "ray from (0, 1, 0) along -z, nearest sphere front at z = -8: t");
  CHECK_THAT(&c, h.inst->shape == SHAPE_SPHERE && h.material == 1 && h.light == -1,
             "the same ray: a sphere of material 1 must be hit, got shape %d, hit.material %d, "
             "hit.light %d", (int)h.inst->shape, h.material, h.light);
  /* Slightly off axis (y = 1.5): the r 2 sphere's front is at
   * z = -10 + sqrt(4 - 0.25), the r 1 sphere's at -9 + sqrt(1 - 0.25), the
   * r 3 sphere's at -12 + sqrt(9 - 0.25): the nearest is the r 2 one. */
  CHECK_REQUIRE(&c, scene_intersect(&s, ray(0, 1.5f, 0, 0, 0, -1), INFINITY, &h),
                "ray from (0, 1.5, 0) along -z: no hit found");
  long double t2 = 10.0L - sqrtl(3.75L);
  CHECK_NEAR(&c, (double)t2, h.t, 1e-5, "ray from (0, 1.5, 0) along -z: the radius-2 sphere's "
             "front is nearest: t = 10 - sqrt(3.75)");
  CHECK_NEAR(&c, 2.0, h.inst->sphere.radius, 0.0, "the same ray: radius of the sphere hit");
  scene_free(&s);
}

Test(scene, the_floor_is_closer_than_the_spheres_behind_it)
{
  Scene s;
  build(&s);
  cr_assert(scene_prepare(&s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  /* From (0, 1, 0) toward (0, 0, -4): meets y = 0 at t = sqrt(17) before
   * any sphere (their lowest points are at z <= -8). */
  Hit h;
  Check c = CHECK(SHAPES, DOC);
  CHECK_REQUIRE(&c, scene_intersect(&s, ray(0, 1, 0, 0, -1, -4), INFINITY, &h),
                "ray from (0, 1, 0) toward (0, 0, -4): no hit found (the floor is there)");
  CHECK_INT(&c, SHAPE_PLANE, h.inst->shape, "ray from (0, 1, 0) toward (0, 0, -4): the floor "
            "(shape %d) is nearer than the spheres", SHAPE_PLANE);
  CHECK_NEAR(&c, (double)sqrtl(17.0L), h.t, 1e-5, "the same ray: t = sqrt(17)");
  CHECK_NEAR(&c, 0.0, h.p.y, 0.0, "the same ray: hit.p.y on the floor y = 0");
  CHECK_NEAR(&c, 1.0, h.n.y, 0.0, "the same ray: hit.n.y");
  /* Upward from below the floor: hits it from behind first. */
  CHECK_REQUIRE(&c, scene_intersect(&s, ray(0, -1, -10, 0, 1, 0), INFINITY, &h),
                "ray from (0, -1, -10) up: no hit found (the floor is 1 above)");
  CHECK_THAT(&c, h.inst->shape == SHAPE_PLANE && h.backface && h.t == 1.0f,
             "ray from (0, -1, -10) up: the floor from behind at t = 1, got shape %d, "
             "backface %d, t = %.9g", (int)h.inst->shape, h.backface, h.t);
  /* Nothing above. */
  CHECK_INT(&c, 0, scene_intersect(&s, ray(0, 5, 0, 0, 1, 0), INFINITY, &h),
            "ray from (0, 5, 0) straight up, nothing there: hit found");
  /* tmax before everything. */
  CHECK_INT(&c, 0, scene_intersect(&s, ray(0, 1, 0, 0, 0, -1), 7.5f, &h),
            "ray from (0, 1, 0) along -z with tmax 7.5, first sphere at 8: hit found");
  scene_free(&s);
}

Test(scene, closest_hit_among_many_spheres_matches_brute_force)
{
  /* 400 spheres on a grid (enough for an acceleration structure), rays from
   * the front: the closest t from the long double quadratic of every sphere.
   * This checks the logic (which sphere, which root, hit or miss), so t may
   * be off by what the quadratic's rounding in float moves it: its terms are
   * about |f|^2, each good to 2^-24 of that, and the square root divides
   * their error by 2 sqrt(disc); the lecture's formula stays within 3 x
   * 2^-24 (|f|^2 / sqrt(disc)) here, 8 are allowed. The last bits are stress
   * test 1's (tests/stress_sphere.c). */
  Scene s;
  scene_init(&s);
  Material m = {.name = "m"};
  cr_assert(scene_add_material(&s, &m), "out of memory");
  for (int k = 0; k < 400; k++)
    add_sphere(&s, (float)(k % 20) - 9.5f, (float)(k / 20) - 9.5f, -10.0f - (float)(k % 7),
               0.3f + 0.05f * (float)(k % 5), 0);
  cr_assert(scene_prepare(&s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  Check ck = CHECK(SPHERES, DOC);
  int decided = 0;
  for (int q = 0; q < 400; q++) {
    Ray r = ray(0.1f, -0.2f, 5.0f, 0.04f * (float)(q % 20) - 0.4f,
                0.04f * (float)(q / 20) - 0.4f, -1.0f);
    long double best = INFINITY, tol = 0.0L;
    bool grazing = false;
    for (int k = 0; k < s.n_shapes; k++) {
      const Sphere *sp = &s.instances[k].sphere;
      long double f[3] = {(long double)r.o.x - sp->center.x, (long double)r.o.y - sp->center.y,
                          (long double)r.o.z - sp->center.z};
      long double len = sqrtl((long double)r.d.x * r.d.x + (long double)r.d.y * r.d.y +
                              (long double)r.d.z * r.d.z);
      long double b = (f[0] * r.d.x + f[1] * r.d.y + f[2] * r.d.z) / len;
      long double ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
      long double c = ff - (long double)sp->radius * sp->radius;
      long double disc = b * b - c; /* r^2 - (distance from the centre to the line)^2 */
      /* Hit or miss is only decidable in float when the line clears the
       * silhouette by more than a few float roundings of the distance
       * (docs/accuracy.md, stress test 2): such rays are not asserted. */
      long double clearance = sp->radius - sqrtl(fmaxl(0.0L, ff - b * b));
      if (fabsl(clearance) < 8.0L * 0x1p-24L * sqrtl(ff))
        grazing = true;
      if (disc >= 0.0L && -b - sqrtl(disc) > 0.0L && -b - sqrtl(disc) < best) {
        best = -b - sqrtl(disc);
        tol = 8.0L * 0x1p-24L * (ff / sqrtl(disc) + sqrtl(ff));
      }
    }
    if (grazing)
      continue;
    decided++;
    Hit h;
    bool hit = scene_intersect(&s, r, INFINITY, &h);
    CHECK_INT(&ck, isfinite(best), hit, "ray %d of 400 into a grid of 400 spheres: hit "
              "(1) or miss (0), as the long double quadratic says", q);
    if (hit && isfinite(best))
      CHECK_NEAR(&ck, (double)best, h.t, (double)tol, "ray %d of 400: t of the nearest "
                 "sphere, as the long double quadratic says (the tolerance is the rounding "
                 "of the quadratic in float)", q);
  }
  CHECK_DONE(&ck);
  cr_assert(decided > 350, "the test's own rays: only %d of 400 clear every silhouette", decided);
  scene_free(&s);
}

Test(scene, occluded_only_before_tmax)
{
  Scene s;
  build(&s);
  cr_assert(scene_prepare(&s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  Ray r = ray(0, 1, 0, 0, 0, -1); /* first occluder at t = 8 */
  Check c = CHECK("sphere_hit_t, plane_hit_t (through scene_occluded)", DOC);
  CHECK_INT(&c, 1, scene_occluded(&s, r, 100.0f), "ray along -z, sphere at t = 8, tmax 100: "
            "occluded");
  CHECK_INT(&c, 1, scene_occluded(&s, r, 8.5f), "the same ray, tmax 8.5: occluded");
  CHECK_INT(&c, 0, scene_occluded(&s, r, 7.9f), "the same ray, tmax 7.9 (the sphere lies "
            "past tmax): occluded");
  CHECK_INT(&c, 0, scene_occluded(&s, ray(0, 5, 0, 0, 1, 0), INFINITY),
            "ray straight up with nothing above: occluded");
  /* The floor occludes a ray going down. */
  CHECK_INT(&c, 1, scene_occluded(&s, ray(0, 1, 0, 0, -1, 0), 1.5f),
            "ray from (0, 1, 0) down, floor at t = 1, tmax 1.5: occluded");
  CHECK_INT(&c, 0, scene_occluded(&s, ray(0, 1, 0, 0, -1, 0), 0.5f),
            "the same ray, tmax 0.5: occluded");
  scene_free(&s);
}

Test(scene, light_shapes_are_seen_but_never_occlude)
{
  Scene s;
  scene_init(&s);
  Material m = {.name = "m"};
  cr_assert(scene_add_material(&s, &m), "out of memory");
  add_sphere(&s, 0, 0, -20, 1, 0);
  Light point = {.type = LIGHT_POINT, .position = vec_make(0, 0, -5), .radius = 0.5f,
                 .power = vec_make(1, 1, 1)};
  Light area = {.type = LIGHT_AREA, .power = vec_make(1, 1, 1),
                .quad = quad_make(vec_make(-1, 2, -11), vec_make(2, 0, 0), vec_make(0, 0, 2))};
  cr_assert(scene_add_light(&s, &point) && scene_add_light(&s, &area), "out of memory");
  cr_assert(scene_prepare(&s, SCENE_CAMERA | SCENE_LIGHTS | SCENE_LIGHT_SHAPES |
                                  SCENE_AREA_LIGHTS), "out of memory");
  /* The camera sees the light's sphere (front at z = -4.5). */
  Hit h;
  Check c = CHECK(SPHERES, DOC);
  CHECK_REQUIRE(&c, scene_intersect(&s, ray(0, 0, 0, 0, 0, -1), INFINITY, &h),
                "ray along -z toward a point light's sphere at z = -5: no hit found");
  CHECK_THAT(&c, h.light == 0 && h.material == -1, "the same ray: the light's "
             "sphere must be hit, got hit.light %d, hit.material %d", h.light, h.material);
  CHECK_NEAR(&c, 4.5, h.t, 1e-6, "the same ray: t of the light's sphere (radius 0.5)");
  /* ... and the area light's quad (y = 2, x in [-1, 1], z in [-11, -9]). */
  cr_assert(scene_intersect(&s, ray(0, 0, -10, 0, 1, 0), INFINITY, &h),
            "quad_hit_t (given code): the ray up into an area light found no hit");
  /* Neither blocks a shadow ray; the lit sphere behind them does. */
  Check o = CHECK("sphere_hit_t (through scene_occluded)", DOC);
  CHECK_INT(&o, 0, scene_occluded(&s, ray(0, 0, 0, 0, 0, -1), 10.0f),
            "shadow ray through a light's sphere only: occluded");
  CHECK_INT(&o, 0, scene_occluded(&s, ray(0, 0, -10, 0, 1, 0), 10.0f),
            "shadow ray through an area light only: occluded");
  CHECK_INT(&o, 1, scene_occluded(&s, ray(0, 0, 0, 0, 0, -1), 30.0f),
            "shadow ray on to the lit sphere at z = -20: occluded");
  scene_free(&s);
}
