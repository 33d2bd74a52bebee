/* Unit tests of ray-plane intersection (step 02): hits, misses, parallel
 * rays, back faces, exact hit points on axis-aligned planes, the error bound
 * p_err of tilted ones. docs/02-intersection.md, "What you write". */
#include "check.h"

#include "plane.h"

#define DOC "docs/02-intersection.md, \"What you write\""

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
  Check c = CHECK("plane_make", "docs/02-intersection.md, \"The math\"");
  CHECK_VEC(&c, vec_make(0, 1, 0), floor_plane().normal, 0.0, "normal (0, 3, 0) stored unit");
  CHECK_VEC(&c, vec_make(0.6f, 0, 0.8f), plane_make(vec_make(0, 0, 0), vec_make(3, 0, 4)).normal,
            1e-7, "normal (3, 0, 4) stored unit");
}

Test(plane, straight_down_hits_at_the_height)
{
  Plane p = floor_plane();
  Ray r = ray(0.5f, 1.0f, 2.0f, 0, -1, 0);
  Check ct = CHECK("plane_hit_t", DOC), f = CHECK("plane_hit_fill", DOC);
  float t = plane_hit_t(&p, r, INFINITY);
  CHECK_NEAR(&ct, 2.0, t, 0.0, "ray from (0.5, 1, 2) straight down to the floor y = -1: t");
  Hit h;
  plane_hit_fill(&p, r, 2.0f, &h);
  CHECK_NEAR(&f, 2.0, h.t, 0.0, "the same ray at t = 2: hit.t");
  CHECK_VEC(&f, vec_make(0.5f, -1.0f, 2.0f), h.p, 0.0, "the same ray at t = 2: hit.p");
  CHECK_VEC(&f, vec_make(0, 1, 0), h.n, 0.0, "the same ray at t = 2: hit.n");
  CHECK_INT(&f, 0, h.backface, "the same ray, from above: hit.backface");
}

Test(plane, oblique_hit_at_the_closed_form_distance)
{
  /* From height 2 above y = -1 at 45 degrees: t = 2 sqrt(2), x = 2. */
  Plane p = floor_plane();
  Ray r = ray(0, 1, 0, 1, -1, 0);
  Check ct = CHECK("plane_hit_t", DOC), f = CHECK("plane_hit_fill", DOC);
  float t = plane_hit_t(&p, r, INFINITY);
  CHECK_REL(&ct, (double)(2.0L * sqrtl(2.0L)), t, 1e-6,
            "ray from (0, 1, 0) at 45 degrees down to the floor y = -1: t = 2 sqrt(2)");
  Hit h;
  plane_hit_fill(&p, r, (float)(2.0L * sqrtl(2.0L)), &h);
  CHECK_VEC(&f, vec_make(2.0f, -1.0f, 0.0f), h.p, 1e-6, "the same ray at t = 2 sqrt(2): hit.p");
}

Test(plane, axis_aligned_hit_lies_exactly_on_the_plane)
{
  /* Whatever rounding o + t d has, an axis-aligned plane's hit has exactly
   * the plane's coordinate, and no error bound. */
  Plane p = plane_make(vec_make(0.0f, 0.1f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  Check ct = CHECK("plane_hit_t", DOC), f = CHECK("plane_hit_fill", DOC);
  for (int k = 1; k < 50; k++) {
    Ray r = ray(0.3f * (float)k, 7.77f, -1.1f * (float)k, 0.17f * (float)k, -1.0f, 0.29f);
    float t = plane_hit_t(&p, r, INFINITY);
    CHECK_THAT(&ct, isfinite(t), "oblique ray %d from y = 7.77 down to the plane y = 0.1: t"
               "\n  expected a hit (t finite)\n  got      %.9g", k, t);
    if (!isfinite(t))
      continue;
    Hit h;
    plane_hit_fill(&p, r, t, &h);
    CHECK_NEAR(&f, 0.1f, h.p.y, 0.0, "oblique ray %d to the plane y = 0.1 (an axis plane): "
               "hit.p.y snapped onto the plane", k);
    CHECK_NEAR(&f, 0.0, h.p_err, 0.0, "oblique ray %d to an axis plane: hit.p_err", k);
  }
  CHECK_DONE(&ct);
  CHECK_DONE(&f);
}

Test(plane, tilted_hit_is_on_the_plane_within_its_error_bound)
{
  vec3s q = vec_make(1.0f, 2.0f, 3.0f);
  Plane p = plane_make(q, vec_make(1.0f, 1.0f, 0.5f));
  Ray r = ray(10.0f, 10.0f, 10.0f, -1.0f, -0.9f, -1.2f);
  Check ct = CHECK("plane_hit_t", DOC), f = CHECK("plane_hit_fill", DOC);
  float t = plane_hit_t(&p, r, INFINITY);
  CHECK_REQUIRE(&ct, isfinite(t), "ray from (10, 10, 10) toward the tilted plane through "
                "(1, 2, 3), normal (1, 1, 0.5): t\n  expected a hit (t finite)\n  got      %.9g",
                t);
  Hit h;
  plane_hit_fill(&p, r, t, &h);
  /* Signed distance of p to the plane, long double, normal (1, 1, 0.5)/1.5. */
  long double dist = (((long double)h.p.x - q.x) + ((long double)h.p.y - q.y) +
                      0.5L * ((long double)h.p.z - q.z)) / 1.5L;
  CHECK_NEAR(&f, 0.0, (double)dist, 1e-6, "the same hit: distance of hit.p from the plane");
  CHECK_THAT(&f, h.p_err > 0.0f && fabsl(dist) <= 3.0L * h.p_err,
             "the same hit: hit.p_err must bound p's error (|distance| <= 3 p_err, p_err > 0)"
             "\n  expected p_err >= %.9g\n  got      p_err = %.9g", (double)(fabsl(dist) / 3.0L),
             h.p_err);
}

Test(plane, pointing_away_misses)
{
  Plane p = floor_plane();
  Check c = CHECK("plane_hit_t", DOC);
  CHECK_NEAR(&c, INFINITY, plane_hit_t(&p, ray(0, 1, 0, 0, 1, 0), INFINITY), 0.0,
             "ray from (0, 1, 0) straight up, floor y = -1 below: a miss is INFINITY");
  CHECK_NEAR(&c, INFINITY, plane_hit_t(&p, ray(0, 1, 0, 1, 0.01f, 0), INFINITY), 0.0,
             "ray from (0, 1, 0) slightly upward, floor y = -1 below: a miss is INFINITY");
}

Test(plane, parallel_ray_misses_without_nan)
{
  Plane p = floor_plane();
  Check c = CHECK("plane_hit_t", DOC);
  CHECK_NEAR(&c, INFINITY, plane_hit_t(&p, ray(0, 1, 0, 1, 0, 0), INFINITY), 0.0,
             "ray parallel to the floor, above it (d.n = 0): a miss is INFINITY");
  CHECK_NEAR(&c, INFINITY, plane_hit_t(&p, ray(0, -1, 0, 0, 0, 1), INFINITY), 0.0,
             "ray inside the floor's plane (0 / 0): a miss is INFINITY, never NaN");
}

Test(plane, behind_the_origin_is_not_hit)
{
  Plane p = plane_make(vec_make(0.0f, 5.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  Check c = CHECK("plane_hit_t", DOC);
  CHECK_NEAR(&c, INFINITY, plane_hit_t(&p, ray(0, 1, 0, 0, -1, 0), INFINITY), 0.0,
             "ray from (0, 1, 0) down, plane y = 5 behind it (t = -4): a miss is INFINITY");
}

Test(plane, back_face_flips_the_normal)
{
  /* From below the floor, going up: t = 2, seen from behind. */
  Plane p = floor_plane();
  Ray r = ray(0, -3, 0, 0, 1, 0);
  Check ct = CHECK("plane_hit_t", DOC), f = CHECK("plane_hit_fill", DOC);
  CHECK_NEAR(&ct, 2.0, plane_hit_t(&p, r, INFINITY), 0.0,
             "ray from (0, -3, 0) up to the floor y = -1, from below: t");
  Hit h;
  plane_hit_fill(&p, r, 2.0f, &h);
  CHECK_INT(&f, 1, h.backface, "the same hit, from behind the plane: hit.backface");
  CHECK_VEC(&f, vec_make(0, -1, 0), h.n, 0.0, "the same hit: hit.n flipped to face the ray");
  CHECK_NEAR(&f, -1.0, h.p.y, 0.0, "the same hit: hit.p.y");
}

Test(plane, tmax_is_respected)
{
  Plane p = floor_plane();
  Ray r = ray(0, 1, 0, 0, -1, 0);
  Check c = CHECK("plane_hit_t", DOC);
  CHECK_NEAR(&c, INFINITY, plane_hit_t(&p, r, 1.5f), 0.0, "hit at t = 2 with tmax = 1.5: a miss");
  CHECK_NEAR(&c, INFINITY, plane_hit_t(&p, r, 2.0f), 0.0,
             "hit at t = 2 with tmax = 2 (t must be < tmax, not <=): a miss");
  CHECK_NEAR(&c, 2.0, plane_hit_t(&p, r, 2.5f), 0.0, "hit at t = 2 with tmax = 2.5: t");
}
