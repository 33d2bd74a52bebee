/* Unit tests of the ray r(t) = o + t d (step 02). docs/02-intersection.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "ray.h"

Test(ray, at_zero_is_the_origin)
{
  Ray r = {.o = vec_make(1.5f, -2.0f, 3.25f), .d = vec_make(0.0f, 0.0f, -1.0f)};
  vec3s p = ray_at(r, 0.0f);
  cr_expect(p.x == 1.5f && p.y == -2.0f && p.z == 3.25f);
}

Test(ray, at_t_along_an_axis_is_exact)
{
  /* o + t d with d = (0, 0, -1), t = 4: (1, 2, 3 - 4). */
  Ray r = {.o = vec_make(1.0f, 2.0f, 3.0f), .d = vec_make(0.0f, 0.0f, -1.0f)};
  vec3s p = ray_at(r, 4.0f);
  cr_expect(p.x == 1.0f && p.y == 2.0f && p.z == -1.0f, "(%g %g %g)", p.x, p.y, p.z);
}

Test(ray, at_t_is_at_distance_t_along_a_diagonal)
{
  /* d = (1, 1, 1)/sqrt(3): ray_at(5 sqrt(3)) = o + (5, 5, 5). */
  float k = (float)(1.0L / sqrtl(3.0L));
  Ray r = {.o = vec_make(-1.0f, 0.5f, 2.0f), .d = vec_make(k, k, k)};
  float t = (float)(5.0L * sqrtl(3.0L));
  vec3s p = ray_at(r, t);
  cr_expect(fabsf(p.x - 4.0f) < 4e-6f && fabsf(p.y - 5.5f) < 4e-6f && fabsf(p.z - 7.0f) < 4e-6f,
            "(%.9g %.9g %.9g)", p.x, p.y, p.z);
  /* Negative t goes backwards. */
  p = ray_at(r, -t);
  cr_expect(fabsf(p.x + 6.0f) < 4e-6f && fabsf(p.y + 4.5f) < 4e-6f && fabsf(p.z + 3.0f) < 4e-6f);
}

Test(ray, spawn_leaves_the_surface_on_the_side_of_the_direction)
{
  Hit hit = {.t = 1.0f, .p = vec_make(0.0f, 1.0f, 0.0f), .n = vec_make(0.0f, 1.0f, 0.0f),
             .p_err = 1e-6f};
  Ray up = ray_spawn(&hit, vec_make(0.0f, 1.0f, 0.0f));
  Ray down = ray_spawn(&hit, vec_make(0.0f, -1.0f, 0.0f));
  /* Pushed past the error bound along n: above for the outgoing ray, below
   * for the one going into the surface. */
  cr_expect(up.o.y > 1.0f + 1e-6f, "up origin %.9g", up.o.y);
  cr_expect(down.o.y < 1.0f - 1e-6f, "down origin %.9g", down.o.y);
  cr_expect(up.o.x == 0.0f && up.o.z == 0.0f && up.d.y == 1.0f && down.d.y == -1.0f);
}
