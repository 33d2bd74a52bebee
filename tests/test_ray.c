/* Unit tests of the ray r(t) = o + t d (step 02; ray_at is given code, the
 * ray every intersection test relies on). docs/02-intersection.md. ray_spawn
 * (step 05) is tested with the shadows, tests/test_shadows.c. */
#include "check.h"

#include "ray.h"

#define DOC "docs/02-intersection.md, \"The math\""

Test(ray, at_zero_is_the_origin)
{
  Ray r = {.o = vec_make(1.5f, -2.0f, 3.25f), .d = vec_make(0.0f, 0.0f, -1.0f)};
  Check c = CHECK("ray_at", DOC);
  CHECK_VEC(&c, r.o, ray_at(r, 0.0f), 0.0, "o + 0 d, o = (1.5, -2, 3.25)");
}

Test(ray, at_t_along_an_axis_is_exact)
{
  /* o + t d with d = (0, 0, -1), t = 4: (1, 2, 3 - 4). */
  Ray r = {.o = vec_make(1.0f, 2.0f, 3.0f), .d = vec_make(0.0f, 0.0f, -1.0f)};
  Check c = CHECK("ray_at", DOC);
  CHECK_VEC(&c, vec_make(1.0f, 2.0f, -1.0f), ray_at(r, 4.0f), 0.0,
            "o = (1, 2, 3), d = (0, 0, -1), t = 4");
}

Test(ray, at_t_is_at_distance_t_along_a_diagonal)
{
  /* d = (1, 1, 1)/sqrt(3): ray_at(5 sqrt(3)) = o + (5, 5, 5). */
  float k = (float)(1.0L / sqrtl(3.0L));
  Ray r = {.o = vec_make(-1.0f, 0.5f, 2.0f), .d = vec_make(k, k, k)};
  float t = (float)(5.0L * sqrtl(3.0L));
  Check c = CHECK("ray_at", DOC);
  CHECK_VEC(&c, vec_make(4.0f, 5.5f, 7.0f), ray_at(r, t), 4e-6,
            "o = (-1, 0.5, 2), d = (1, 1, 1)/sqrt(3), t = 5 sqrt(3)");
  CHECK_VEC(&c, vec_make(-6.0f, -4.5f, -3.0f), ray_at(r, -t), 4e-6,
            "the same ray at t = -5 sqrt(3) (backwards)");
}
