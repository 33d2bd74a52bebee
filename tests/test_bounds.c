/* The shapes' bounding boxes (NAME_bounds, scene_instance_bounds: given
 * code, common/box.h) against boxes computed by hand: each holds its shape's
 * exact box and exceeds it by no more than the documented margin; an
 * unbounded plane's box is infinite. docs/extending.md, "Adding a shape". */
#include "check.h"

#include "scene.h"
#include "scene_index.h"

#define DOC "docs/extending.md, \"Adding a shape\""

/* The slack a box may add to the exact one: box_margin's 2^-16 of the size
 * and 2^-20 of the magnitude, with room for its rounding. */
static double slack(double size, double magnitude)
{
  return 0x1p-15 * size + 0x1p-19 * magnitude;
}

/* got holds the exact box [lo, hi] and exceeds it by at most `tol` on each
 * side; an infinite bound of the exact box must be the same infinity. */
static void check_box(Check *c, const char *what, Box got, vec3s lo, vec3s hi, double tol)
{
  for (int a = 0; a < 3; a++) {
    double l = lo.raw[a], h = hi.raw[a], gl = got.min.raw[a], gh = got.max.raw[a];
    bool ok_lo = isinf(l) ? gl == l : (gl <= l && gl >= l - tol);
    bool ok_hi = isinf(h) ? gh == h : (gh >= h && gh <= h + tol);
    CHECK_THAT(c, ok_lo && ok_hi,
               "%s, axis %c\n  expected [%.9g, %.9g] (outward by at most %.3g)\n"
               "  got      [%.9g, %.9g]",
               what, "xyz"[a], l, h, tol, gl, gh);
  }
}

Test(bounds, sphere_cube)
{
  Check c = CHECK("sphere_bounds", DOC);
  Sphere s = {.center = vec_make(1, 2, 3), .radius = 0.5f};
  check_box(&c, "sphere centre (1, 2, 3), radius 0.5", sphere_bounds(&s),
            vec_make(0.5f, 1.5f, 2.5f), vec_make(1.5f, 2.5f, 3.5f), slack(0.5, 3.5));
  Sphere far = {.center = vec_make(-1e5f, 0, 7), .radius = 2.0f};
  check_box(&c, "sphere centre (-1e5, 0, 7), radius 2", sphere_bounds(&far),
            vec_make(-100002.0f, -2, 5), vec_make(-99998.0f, 2, 9), slack(2, 1e5 + 2));
  Sphere tiny = {.center = vec_make(0, 0, 0), .radius = 1e-4f};
  check_box(&c, "sphere centre (0, 0, 0), radius 1e-4", sphere_bounds(&tiny),
            vec_make(-1e-4f, -1e-4f, -1e-4f), vec_make(1e-4f, 1e-4f, 1e-4f), slack(1e-4, 1e-4));
  CHECK_DONE(&c);
}

Test(bounds, plane_is_unbounded)
{
  Check c = CHECK("plane_bounds", DOC);
  Plane floor = plane_make(vec_make(5, -1, 5), vec_make(0, 3, 0));
  check_box(&c, "plane y = -1 (normal (0, 3, 0)): flat along y, infinite along x and z",
            plane_bounds(&floor), vec_make(-INFINITY, -1, -INFINITY),
            vec_make(INFINITY, -1, INFINITY), slack(0, 1));
  CHECK_INT(&c, 0, box_is_bounded(plane_bounds(&floor)), "plane y = -1: box_is_bounded");
  Plane tilted = plane_make(vec_make(0, 0, 0), vec_make(1, 1, 0));
  check_box(&c, "plane through 0 with normal (1, 1, 0): infinite along every axis",
            plane_bounds(&tilted), vec_make(-INFINITY, -INFINITY, -INFINITY),
            vec_make(INFINITY, INFINITY, INFINITY), 0);
  CHECK_DONE(&c);
}

Test(bounds, quad_corners)
{
  Check c = CHECK("quad_bounds", DOC);
  Quad flat = quad_make(vec_make(0, 0, 0), vec_make(2, 0, 0), vec_make(0, 0, 3));
  check_box(&c, "quad corner 0, edges (2, 0, 0), (0, 0, 3)", quad_bounds(&flat),
            vec_make(0, 0, 0), vec_make(2, 0, 3), slack(5, 3));
  /* Corners (1, 1, 1), (2, 2, 1), (1, 0, 3), (2, 1, 3). */
  Quad tilted = quad_make(vec_make(1, 1, 1), vec_make(1, 1, 0), vec_make(0, -1, 2));
  check_box(&c, "quad corner (1, 1, 1), edges (1, 1, 0), (0, -1, 2)", quad_bounds(&tilted),
            vec_make(1, 0, 1), vec_make(2, 2, 3), slack(3, 3));
  CHECK_DONE(&c);
}

Test(bounds, disc_extent_per_axis)
{
  Check c = CHECK("disc_bounds", DOC);
  Disc flat = disc_make(vec_make(0, 0, 0), vec_make(0, 0, 1), 2.0f);
  check_box(&c, "disc centre 0, normal +z, radius 2", disc_bounds(&flat), vec_make(-2, -2, 0),
            vec_make(2, 2, 0), slack(2, 2));
  /* Normal (0, 1, 1)/sqrt 2, radius 1: along x the disc reaches 1, along y
   * and z 1/sqrt 2 (sqrt(1 - n_i^2)). */
  Disc tilted = disc_make(vec_make(1, 2, 3), vec_make(0, 1, 1), 1.0f);
  double h = 1.0 / sqrt(2.0);
  check_box(&c, "disc centre (1, 2, 3), normal (0, 1, 1), radius 1", disc_bounds(&tilted),
            vec_make(0, (float)(2 - h), (float)(3 - h)),
            vec_make(2, (float)(2 + h), (float)(3 + h)), slack(1, 4) + 1e-7);
  CHECK_DONE(&c);
}

Test(bounds, instance_takes_its_shape)
{
  Check c = CHECK("scene_instance_bounds", DOC);
  Sphere s = {.center = vec_make(1, 2, 3), .radius = 0.5f};
  Plane pl = plane_make(vec_make(0, -1, 0), vec_make(0, 1, 0));
  Quad q = quad_make(vec_make(0, 0, 0), vec_make(2, 0, 0), vec_make(0, 0, 3));
  Disc d = disc_make(vec_make(0, 0, 0), vec_make(0, 0, 1), 2.0f);
  Instance in[] = {{.shape = SHAPE_SPHERE, .sphere = s}, {.shape = SHAPE_PLANE, .plane = pl},
                   {.shape = SHAPE_QUAD, .quad = &q}, {.shape = SHAPE_DISC, .disc = d}};
  Box want[] = {sphere_bounds(&s), plane_bounds(&pl), quad_bounds(&q), disc_bounds(&d)};
  for (int k = 0; k < 4; k++) {
    Box got = scene_instance_bounds(&in[k]);
    CHECK_THAT(&c, memcmp(&got, &want[k], sizeof got) == 0,
               "a %s instance: its shape's own box\n  expected min (%g, %g, %g)\n"
               "  got      min (%g, %g, %g)",
               scene_shape_name(in[k].shape), want[k].min.x, want[k].min.y, want[k].min.z,
               got.min.x, got.min.y, got.min.z);
  }
  CHECK_DONE(&c);
}
