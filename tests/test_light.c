/* Unit tests of the lights' incident radiance (step 04): point light
 * L_i = P / r^2, directional light L_i = E from -direction. docs/04-phong.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "light.h"

static bool near3(vec3s v, long double x, long double y, long double z, long double tol)
{
  return fabsl(v.x - x) <= tol && fabsl(v.y - y) <= tol && fabsl(v.z - z) <= tol;
}

Test(light, point_light_falls_off_as_inverse_square)
{
  /* Light 4 units above along +z: L_i = (16, 32, 48) / 16, l = +z. */
  Light L = {.type = LIGHT_POINT, .position = vec_make(1, 2, 3), .power = vec_make(16, 32, 48)};
  vec3s l;
  float dist;
  vec3s li = light_incident(&L, vec_make(1, 2, -1), 0.0f, &l, &dist);
  cr_expect(li.x == 1.0f && li.y == 2.0f && li.z == 3.0f, "L_i (%g %g %g)", li.x, li.y, li.z);
  cr_expect(l.x == 0.0f && l.y == 0.0f && l.z == 1.0f && dist == 4.0f);
}

Test(light, point_light_off_axis)
{
  /* From the origin to (1, 2, 2): r = 3, L_i = P / 9, l = (1, 2, 2) / 3. */
  Light L = {.type = LIGHT_POINT, .position = vec_make(1, 2, 2), .power = vec_make(9, 4.5f, 1)};
  vec3s l;
  float dist;
  vec3s li = light_incident(&L, vec_make(0, 0, 0), 1e-6f, &l, &dist);
  cr_expect(near3(li, 1.0L, 0.5L, 1.0L / 9.0L, 1e-7L), "L_i (%.9g %.9g %.9g)", li.x, li.y, li.z);
  cr_expect(near3(l, 1.0L / 3, 2.0L / 3, 2.0L / 3, 1e-7L), "l (%.9g %.9g %.9g)", l.x, l.y, l.z);
  cr_expect(fabsf(dist - 3.0f) < 1e-6f);
  /* Twice as far: a quarter of the radiance. */
  vec3s li2 = light_incident(&L, vec_make(-1, -2, -2), 0.0f, &l, &dist);
  cr_expect(near3(li2, 0.25L, 0.125L, 1.0L / 36.0L, 1e-7L));
  cr_expect(fabsf(dist - 6.0f) < 1e-6f);
}

Test(light, directional_light_is_constant)
{
  /* direction (1, -2, 2)/3 (the parser stores it unit): l = (-1, 2, -2)/3. */
  Light L = {.type = LIGHT_DIRECTIONAL, .direction = vec_make(1.0f / 3, -2.0f / 3, 2.0f / 3),
             .irradiance = vec_make(0.3f, 0.2f, 0.1f)};
  vec3s l;
  float dist;
  vec3s points[3] = {vec_make(0, 0, 0), vec_make(100, -50, 7), vec_make(-1e4f, 3, 1e4f)};
  for (int k = 0; k < 3; k++) {
    vec3s li = light_incident(&L, points[k], 0.0f, &l, &dist);
    cr_expect(li.x == 0.3f && li.y == 0.2f && li.z == 0.1f, "point %d: L_i = E", k);
    cr_expect(near3(l, -1.0L / 3, 2.0L / 3, -2.0L / 3, 1e-7L), "point %d: l", k);
    cr_expect(isinf(dist) && dist > 0.0f, "point %d: distance %g", k, dist);
  }
}

Test(light, point_light_at_the_shaded_point_gives_zero)
{
  Light L = {.type = LIGHT_POINT, .position = vec_make(1, 1, 1), .power = vec_make(1, 1, 1)};
  vec3s l;
  float dist;
  vec3s li = light_incident(&L, vec_make(1, 1, 1), 0.0f, &l, &dist);
  cr_expect(li.x == 0.0f && li.y == 0.0f && li.z == 0.0f, "L_i (%g %g %g)", li.x, li.y, li.z);
  cr_expect(vec_is_finite(l) && vec_is_finite(li));
  /* Closer than the point's error bound: also zero, no 1/r^2 blow-up. */
  li = light_incident(&L, vec_make(1, 1, 1 + 1e-7f), 1e-6f, &l, &dist);
  cr_expect(li.x == 0.0f && li.y == 0.0f && li.z == 0.0f);
  cr_expect(vec_is_finite(l));
}
