/* The textbook geometry the robust code replaces, kept for comparison only:
 * the stress tests measure it beside common/ (docs/accuracy.md) and
 * bench/robust-cost.c times it. Never used by a step. */
#ifndef RT_TEXTBOOK_H
#define RT_TEXTBOOK_H

#include "plane.h"
#include "sphere.h"

/* The fixed shadow-ray offset of the textbook ("shadow bias"), in scene units. */
#define TEXTBOOK_EPS 1e-4f

/* Ray-sphere as usually taught: t = -b -+ sqrt(b^2 - c), b = f.d, c = f.f - r^2. */
static inline float textbook_sphere_t(const Sphere *s, Ray r, float tmax)
{
  vec3s f = glms_vec3_sub(r.o, s->center);
  float b = glms_vec3_dot(f, r.d);
  float c = glms_vec3_dot(f, f) - s->radius * s->radius;
  float disc = b * b - c;
  if (disc < 0.0f)
    return INFINITY;
  float sq = sqrtf(disc);
  float t = -b - sq;
  if (t > 0.0f && t < tmax)
    return t;
  t = -b + sq;
  return (t > 0.0f && t < tmax) ? t : INFINITY;
}

/* The robust ray-sphere of common/sphere.c (quick reject included) with
 * b = -f.d and c = f.f - r^2 formed in float from the rounded f instead of in
 * double (docs/02-intersection.md's first refinement left out): the stress
 * tests and bench/robust-cost.c price that choice. */
static inline float float_bc_sphere_t(const Sphere *s, Ray r, float tmax)
{
  vec3s f = glms_vec3_sub(r.o, s->center);
  float fd = glms_vec3_dot(f, r.d), ff = glms_vec3_dot(f, f);
  if (ff - fd * fd > s->radius * s->radius + 0x1p-17f * ff)
    return INFINITY;
  float b = -fd;
  vec3s to_line = glms_vec3_add(f, glms_vec3_scale(r.d, b));
  to_line = glms_vec3_sub(to_line, glms_vec3_scale(r.d, glms_vec3_dot(to_line, r.d)));
  float disc = s->radius * s->radius - glms_vec3_dot(to_line, to_line);
  if (!(disc >= 0.0f))
    return INFINITY;
  float c = ff - s->radius * s->radius;
  float q = b + copysignf(sqrtf(disc), b);
  float t0 = c / q, t1 = q;
  if (t0 > t1) {
    float tmp = t0;
    t0 = t1;
    t1 = tmp;
  }
  if (t0 > 0.0f && t0 < tmax)
    return t0;
  return (t1 > 0.0f && t1 < tmax) ? t1 : INFINITY;
}

/* p = o + t d, n = (p - c) / r: no refinement, no error bound. */
static inline void textbook_sphere_fill(const Sphere *s, Ray r, float t, Hit *hit)
{
  hit->t = t;
  hit->p = ray_at(r, t);
  vec3s n = glms_vec3_scale(glms_vec3_sub(hit->p, s->center), 1.0f / s->radius);
  hit->backface = glms_vec3_dot(n, r.d) > 0.0f;
  hit->n = hit->backface ? glms_vec3_negate(n) : n;
  hit->p_err = 0.0f;
}

static inline float textbook_plane_t(const Plane *pl, Ray r, float tmax)
{
  float t = glms_vec3_dot(glms_vec3_sub(pl->point, r.o), pl->normal) /
            glms_vec3_dot(r.d, pl->normal);
  return (t > 0.0f && t < tmax) ? t : INFINITY;
}

static inline void textbook_plane_fill(const Plane *pl, Ray r, float t, Hit *hit)
{
  hit->t = t;
  hit->p = ray_at(r, t);
  hit->backface = glms_vec3_dot(r.d, pl->normal) > 0.0f;
  hit->n = hit->backface ? glms_vec3_negate(pl->normal) : pl->normal;
  hit->p_err = 0.0f;
}

/* The shadow ray of the textbook: start TEXTBOOK_EPS along the normal. */
static inline Ray textbook_spawn(const Hit *hit, vec3s dir)
{
  Ray r = {.o = glms_vec3_add(hit->p, glms_vec3_scale(hit->n, TEXTBOOK_EPS)), .d = dir};
  return r;
}

#endif
