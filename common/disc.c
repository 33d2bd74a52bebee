/* Ray-disc intersection (common/disc.h): the disc's plane, then the distance
 * from the centre. Given code, as the area lights' quad.c. */
#include "disc.h"

#include "quad.h" /* flat_hit_fill */

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
