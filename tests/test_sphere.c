/* Unit tests of ray-sphere intersection (step 02): each root case, rays from
 * inside, spheres behind, tmax, normals facing the ray. docs/02-intersection.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "sphere.h"

static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz)
{
  Ray r = {.o = vec_make(ox, oy, oz), .d = glms_vec3_normalize(vec_make(dx, dy, dz))};
  return r;
}

/* Unit sphere 5 units down -z: a ray from the origin along -z meets it at
 * t = 4 and t = 6. */
static const Sphere S = {.center = {.x = 0.0f, .y = 0.0f, .z = -5.0f}, .radius = 1.0f};

Test(sphere, two_roots_gives_the_nearest)
{
  float t = sphere_hit_t(&S, ray(0, 0, 0, 0, 0, -1), INFINITY);
  cr_expect(t == 4.0f, "t = %.9g, expected 4", t);
  Hit h;
  sphere_hit_fill(&S, ray(0, 0, 0, 0, 0, -1), t, &h);
  cr_expect(h.t == 4.0f && h.p.x == 0.0f && h.p.y == 0.0f && h.p.z == -4.0f);
  cr_expect(h.n.x == 0.0f && h.n.y == 0.0f && h.n.z == 1.0f, "n (%g %g %g)", h.n.x, h.n.y, h.n.z);
  cr_expect(!h.backface);
}

Test(sphere, oblique_hit_matches_the_long_double_quadratic)
{
  Sphere s = {.center = vec_make(0.5f, 0.1f, -6.0f), .radius = 1.3f};
  Ray r = ray(0.3f, -0.2f, 0.0f, 0.1f, 0.2f, -1.0f);
  /* |o + t d - c|^2 = R^2: t^2 + 2 (f.d) t + f.f - R^2 = 0, f = o - c, from
   * the float inputs in long double. */
  long double f[3] = {(long double)r.o.x - s.center.x, (long double)r.o.y - s.center.y,
                      (long double)r.o.z - s.center.z};
  long double d[3] = {r.d.x, r.d.y, r.d.z};
  long double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  long double b = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
  long double c = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - (long double)s.radius * s.radius;
  long double t0 = (-b - sqrtl(b * b - dd * c)) / dd;
  float t = sphere_hit_t(&s, r, INFINITY);
  cr_expect(fabsl(t - t0) <= 1e-5L * t0, "t = %.9g, expected %.12Lg", t, t0);
  Hit h;
  sphere_hit_fill(&s, r, t, &h);
  vec3s rel = glms_vec3_sub(h.p, s.center);
  cr_expect(fabsf(glms_vec3_norm(rel) - s.radius) <= 4e-7f, "p is %.9g from the centre",
            glms_vec3_norm(rel));
  cr_expect(fabsf(glms_vec3_norm(h.n) - 1.0f) <= 1e-6f);
  cr_expect(glms_vec3_dot(h.n, r.d) < 0.0f, "normal must face the ray");
  cr_expect(!h.backface);
}

Test(sphere, tangent_ray_touches_once)
{
  /* The line x = 1 grazes the unit sphere at (1, 0, -5): discriminant 0. */
  float t = sphere_hit_t(&S, ray(1, 0, 0, 0, 0, -1), INFINITY);
  cr_expect(t == 5.0f, "t = %.9g, expected 5", t);
}

Test(sphere, miss_returns_infinity)
{
  cr_expect(isinf(sphere_hit_t(&S, ray(1.001f, 0, 0, 0, 0, -1), INFINITY)));
  cr_expect(isinf(sphere_hit_t(&S, ray(0, 0, 0, 0, 1, 0), INFINITY)));
  cr_expect(isinf(sphere_hit_t(&S, ray(0, 0, 0, 1, 0, -1), INFINITY))); /* 45 degrees off */
}

Test(sphere, origin_inside_hits_the_far_side_from_behind)
{
  /* From the centre, the sphere is 1 away in every direction. */
  Ray r = ray(0, 0, -5, 0, 1, 0);
  float t = sphere_hit_t(&S, r, INFINITY);
  cr_expect(t == 1.0f, "t = %.9g", t);
  Hit h;
  sphere_hit_fill(&S, r, t, &h);
  cr_expect(h.backface, "the ray leaves the sphere: backface");
  cr_expect(h.n.x == 0.0f && h.n.y == -1.0f && h.n.z == 0.0f,
            "normal (%g %g %g) must be flipped to face the ray", h.n.x, h.n.y, h.n.z);
  cr_expect(h.p.y == 0.0f + 1.0f && h.p.z == -5.0f);
  /* Off-centre inside: from (0, 0, -5.5) along -z, the far side at t = 0.5. */
  t = sphere_hit_t(&S, ray(0, 0, -5.5f, 0, 0, -1), INFINITY);
  cr_expect(t == 0.5f, "t = %.9g", t);
  t = sphere_hit_t(&S, ray(0, 0, -5.5f, 0, 0, 1), INFINITY);
  cr_expect(t == 1.5f, "t = %.9g", t);
}

Test(sphere, behind_the_origin_is_not_hit)
{
  /* Both roots negative: the sphere is at t = -6 .. -4. */
  cr_expect(isinf(sphere_hit_t(&S, ray(0, 0, 0, 0, 0, 1), INFINITY)));
}

Test(sphere, tmax_is_respected)
{
  Ray r = ray(0, 0, 0, 0, 0, -1);
  cr_expect(isinf(sphere_hit_t(&S, r, 3.0f)), "tmax 3 < 4: no hit");
  cr_expect(isinf(sphere_hit_t(&S, r, 4.0f)), "t must be < tmax, not <=");
  cr_expect(sphere_hit_t(&S, r, 4.5f) == 4.0f);
  /* From inside with tmax before the far side. */
  cr_expect(isinf(sphere_hit_t(&S, ray(0, 0, -5, 0, 0, -1), 0.5f)));
}

Test(sphere, normal_always_faces_the_ray)
{
  /* Rays from many directions toward and from inside the sphere. */
  Sphere s = {.center = vec_make(1.0f, 2.0f, 3.0f), .radius = 2.0f};
  for (int k = 0; k < 100; k++) {
    float a = 0.37f * (float)k, b = 0.11f * (float)k;
    vec3s d = glms_vec3_normalize(vec_make(cosf(a) * cosf(b), sinf(b), sinf(a) * cosf(b)));
    vec3s o_out = glms_vec3_sub(s.center, glms_vec3_scale(d, 10.0f));
    vec3s o_in = glms_vec3_add(s.center, glms_vec3_scale(d, 0.5f * (float)(k % 3) - 0.5f));
    Ray rays[2] = {{o_out, d}, {o_in, d}};
    for (int q = 0; q < 2; q++) {
      float t = sphere_hit_t(&s, rays[q], INFINITY);
      cr_assert(isfinite(t), "ray %d/%d missed", k, q);
      Hit h;
      sphere_hit_fill(&s, rays[q], t, &h);
      cr_expect(glms_vec3_dot(h.n, d) < 0.0f, "ray %d/%d: n.d >= 0", k, q);
      cr_expect(h.backface == (q == 1), "ray %d/%d: backface %d", k, q, h.backface);
      cr_expect(fabsf(t - (q == 0 ? 8.0f : 2.0f - (0.5f * (float)(k % 3) - 0.5f))) < 1e-5f,
                "ray %d/%d: t = %.9g", k, q, t);
    }
  }
}
