/* Ray-disc intersection (common/disc.h): the disc's plane, then the distance
 * from the centre. Given code, as the area lights' quad.c. */
#include "disc.h"

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
  vec3s p = ray_at(r, t);
  float off = glms_vec3_dot(glms_vec3_sub(p, d->center), d->normal);
  hit->t = t;
  hit->p = glms_vec3_sub(p, glms_vec3_scale(d->normal, off));
  hit->backface = glms_vec3_dot(r.d, d->normal) > 0.0f;
  hit->n = hit->backface ? glms_vec3_negate(d->normal) : d->normal;
  hit->p_err = RAY_POINT_ERR * (vec_max_abs(hit->p) + vec_max_abs(d->center));
}
