/* Ray-disc intersection (common/disc.h): the disc's plane, then the distance
 * from the centre. Given code, as the area lights' quad.c. */
#include "disc.h"

#include "box.h"
#include "quad.h" /* flat_hit_fill */
#include "surface.h"

Disc disc_make(vec3s center, vec3s normal, float radius)
{
  Disc d = {.center = center, .normal = glms_vec3_normalize(normal), .radius = radius};
  return d;
}

float disc_hit_t(const Disc *d, Ray r, float tmax)
{
  /* The plane: (o + t d - c) . n = 0, t = (c - o) . n / (d . n). */
  float d_n = glms_vec3_dot(r.d, d->normal);
  if (d_n == 0.0f)
    return INFINITY;
  float t = glms_vec3_dot(glms_vec3_sub(d->center, r.o), d->normal) / d_n;
  if (!(t > 0.0f && t < tmax))
    return INFINITY;
  /* Within the radius: |p - c|^2 <= r^2 (both below FLT_MAX for coordinates
   * and radii within the scene's limits). */
  vec3s rel = glms_vec3_sub(ray_at(r, t), d->center);
  return glms_vec3_dot(rel, rel) <= d->radius * d->radius ? t : INFINITY;
}

void disc_hit_fill(const Disc *d, Ray r, float t, Hit *hit)
{
  flat_hit_fill(d->center, d->normal, r, t, hit);
}

/* The box of the disc: along axis i it reaches radius * sqrt(1 - n_i^2)
 * from the centre (n the unit normal), padded by box_margin. */
Box disc_bounds(const Disc *d)
{
  /* sqrt(1 - n_x^2) as sqrt(n_y^2 + n_z^2): no cancellation for n near an
   * axis. */
  vec3s n2 = glms_vec3_mul(d->normal, d->normal);
  vec3s half = glms_vec3_scale(vec_make(sqrtf(n2.y + n2.z), sqrtf(n2.x + n2.z), sqrtf(n2.x + n2.y)),
                               d->radius);
  float pad = box_margin(d->radius, vec_max_abs(d->center) + d->radius);
  return box_around(d->center, half, pad);
}

/* For the shape conformance suite: the disc of radius `size` centred at
 * `at` facing `axis`, and its surface in long double: the point u radius
 * from the centre at angle 2 pi v in the disc's plane; on the disc for
 * |u| <= 1, false past it. */
Disc disc_example(vec3s at, float size, vec3s axis)
{
  return disc_make(at, axis, size);
}

bool disc_surface(const Disc *d, long double u, long double v, SurfacePoint *sp)
{
  const long double pi = 3.141592653589793238462643383279502884L;
  long double c[3], t1[3], t2[3];
  surface_ld(d->center, c);
  surface_ld(d->normal, sp->n);
  surface_normalize(sp->n);
  surface_basis(sp->n, t1, t2);
  long double r = (long double)d->radius * u, ca = cosl(2 * pi * v), sa = sinl(2 * pi * v);
  for (int a = 0; a < 3; a++)
    sp->p[a] = c[a] + r * (ca * t1[a] + sa * t2[a]);
  return fabsl(u) <= 1;
}
