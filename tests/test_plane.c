/* Unit tests of ray-plane intersection (step 02): hits, misses, parallel
 * rays, back faces, exact hit points on axis-aligned planes.
 * docs/02-intersection.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "plane.h"

static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz)
{
  Ray r = {.o = vec_make(ox, oy, oz), .d = glms_vec3_normalize(vec_make(dx, dy, dz))};
  return r;
}

/* The floor y = -1, normal up. */
static Plane floor_plane(void)
{
  return plane_make(vec_make(0.0f, -1.0f, 0.0f), vec_make(0.0f, 3.0f, 0.0f));
}

Test(plane, make_normalizes_the_normal)
{
  Plane p = floor_plane();
  cr_expect(p.normal.x == 0.0f && p.normal.y == 1.0f && p.normal.z == 0.0f);
  Plane q = plane_make(vec_make(0, 0, 0), vec_make(3.0f, 0.0f, 4.0f));
  cr_expect(fabsf(q.normal.x - 0.6f) < 1e-7f && fabsf(q.normal.z - 0.8f) < 1e-7f);
}

Test(plane, straight_down_hits_at_the_height)
{
  Plane p = floor_plane();
  Ray r = ray(0.5f, 1.0f, 2.0f, 0, -1, 0);
  float t = plane_hit_t(&p, r, INFINITY);
  cr_expect(t == 2.0f, "t = %.9g", t);
  Hit h;
  plane_hit_fill(&p, r, t, &h);
  cr_expect(h.p.x == 0.5f && h.p.y == -1.0f && h.p.z == 2.0f);
  cr_expect(h.n.y == 1.0f && !h.backface);
}

Test(plane, oblique_hit_at_the_closed_form_distance)
{
  /* From height 2 above y = -1 at 45 degrees: t = 2 sqrt(2), x = 2. */
  Plane p = floor_plane();
  Ray r = ray(0, 1, 0, 1, -1, 0);
  float t = plane_hit_t(&p, r, INFINITY);
  cr_expect(fabsl(t - 2.0L * sqrtl(2.0L)) < 1e-6L, "t = %.9g", t);
  Hit h;
  plane_hit_fill(&p, r, t, &h);
  cr_expect(fabsf(h.p.x - 2.0f) < 1e-6f);
}

Test(plane, axis_aligned_hit_lies_exactly_on_the_plane)
{
  /* Whatever rounding o + t d has, an axis-aligned plane's hit has exactly
   * the plane's coordinate (and no error bound). */
  Plane p = plane_make(vec_make(0.0f, 0.1f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  for (int k = 1; k < 50; k++) {
    Ray r = ray(0.3f * (float)k, 7.77f, -1.1f * (float)k, 0.17f * (float)k, -1.0f, 0.29f);
    float t = plane_hit_t(&p, r, INFINITY);
    cr_assert(isfinite(t));
    Hit h;
    plane_hit_fill(&p, r, t, &h);
    cr_expect(h.p.y == 0.1f, "ray %d: y = %a, plane at %a", k, h.p.y, 0.1f);
    cr_expect(h.p_err == 0.0f);
  }
}

Test(plane, tilted_hit_is_on_the_plane_within_its_error_bound)
{
  vec3s q = vec_make(1.0f, 2.0f, 3.0f);
  Plane p = plane_make(q, vec_make(1.0f, 1.0f, 0.5f));
  Ray r = ray(10.0f, 10.0f, 10.0f, -1.0f, -0.9f, -1.2f);
  float t = plane_hit_t(&p, r, INFINITY);
  cr_assert(isfinite(t));
  Hit h;
  plane_hit_fill(&p, r, t, &h);
  /* Signed distance of p to the plane, long double, normal (1, 1, 0.5)/1.5. */
  long double dist = (((long double)h.p.x - q.x) + ((long double)h.p.y - q.y) +
                      0.5L * ((long double)h.p.z - q.z)) / 1.5L;
  cr_expect(fabsl(dist) <= 1e-6L, "p is %Lg off the plane", dist);
  cr_expect(h.p_err > 0.0f && fabsl(dist) <= 3.0L * h.p_err);
}

Test(plane, pointing_away_misses)
{
  Plane p = floor_plane();
  cr_expect(isinf(plane_hit_t(&p, ray(0, 1, 0, 0, 1, 0), INFINITY)));
  cr_expect(isinf(plane_hit_t(&p, ray(0, 1, 0, 1, 0.01f, 0), INFINITY)));
}

Test(plane, parallel_ray_misses_without_nan)
{
  Plane p = floor_plane();
  float t = plane_hit_t(&p, ray(0, 1, 0, 1, 0, 0), INFINITY);
  cr_expect(isinf(t) && t > 0.0f, "t = %g", t);
  /* In the plane itself: 0 / 0. */
  t = plane_hit_t(&p, ray(0, -1, 0, 0, 0, 1), INFINITY);
  cr_expect(isinf(t) && t > 0.0f, "t = %g (must not be NaN)", t);
}

Test(plane, behind_the_origin_is_not_hit)
{
  Plane p = plane_make(vec_make(0.0f, 5.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  cr_expect(isinf(plane_hit_t(&p, ray(0, 1, 0, 0, -1, 0), INFINITY)));
}

Test(plane, back_face_flips_the_normal)
{
  /* From below the floor, going up: t = 2, seen from behind. */
  Plane p = floor_plane();
  Ray r = ray(0, -3, 0, 0, 1, 0);
  float t = plane_hit_t(&p, r, INFINITY);
  cr_expect(t == 2.0f, "t = %.9g", t);
  Hit h;
  plane_hit_fill(&p, r, t, &h);
  cr_expect(h.backface);
  cr_expect(h.n.x == 0.0f && h.n.y == -1.0f && h.n.z == 0.0f);
  cr_expect(h.p.y == -1.0f);
}

Test(plane, tmax_is_respected)
{
  Plane p = floor_plane();
  Ray r = ray(0, 1, 0, 0, -1, 0);
  cr_expect(isinf(plane_hit_t(&p, r, 1.5f)));
  cr_expect(isinf(plane_hit_t(&p, r, 2.0f)), "t must be < tmax");
  cr_expect(plane_hit_t(&p, r, 2.5f) == 2.0f);
}
