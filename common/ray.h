/* Ray r(t) = o + t d with unit d (so t is a distance) and the hit record.
 * Introduced in step 02; docs/02-intersection.md. Spawning secondary rays
 * without self-intersection is in docs/accuracy.md. */
#ifndef RT_RAY_H
#define RT_RAY_H

#include <stdbool.h>
#include "vec.h"

typedef struct Ray {
  vec3s o; /* origin, world space */
  vec3s d; /* unit direction, world space */
} Ray;

struct Instance;

/* What a closest-hit query returns, the lecture's Hit (position, normal,
 * backfacing, material or light). The normal always faces against the ray;
 * `backface` says it was flipped (the ray came from inside or behind). */
typedef struct Hit {
  float t;                     /* distance along the ray */
  vec3s p;                     /* point, refined onto the surface */
  vec3s n;                     /* unit normal, n . d <= 0 */
  float p_err;                 /* bound on the error of each coordinate of p */
  bool backface;               /* the ray hit the surface from behind */
  int material;                /* the lit shape's material (Scene.materials),
                                * -1 for a light's shape */
  int light;                   /* the light whose shape was hit (Scene.lights),
                                * -1 for a lit shape */
  const struct Instance *inst; /* the instance hit (for the tools and tests) */
} Hit;

/* The point at distance t along the ray. */
static inline vec3s ray_at(Ray r, float t)
{
  return glms_vec3_add(r.o, glms_vec3_scale(r.d, t));
}

/* Bound on the error of a refined hit point, relative to the magnitude of the
 * coordinates involved: 4 float ulps (2^-22 = 4 x 2^-24). The shapes' *_fill
 * set p_err from it (docs/accuracy.md). */
static const float RAY_POINT_ERR = 0x1p-22f;

/* A shadow ray toward a light at distance `dist` stops this much short of it
 * (relative), so that the light's own surface, or a point on it, never counts
 * as an occluder: tmax = dist (1 - 2^-20). */
static inline float ray_shadow_tmax(float dist)
{
  return dist * (1.0f - 0x1p-20f);
}

/* A ray leaving the hit point in unit direction `dir`, its origin pushed off
 * the surface just past the point's error bound, on the side `dir` goes to
 * (step 05; docs/05-shadows.md, docs/accuracy.md). */
static inline Ray ray_spawn(const Hit *hit, vec3s dir)
{
  /* BEGIN SOLUTION step 05 */
  /* The push is 2 |n|_1 p_err: the error box's extent along n, doubled, so
   * the origin is outside the box of possible exact points at any scene
   * scale. */
  float push = 2.0f * hit->p_err * vec_sum_abs(hit->n);
  if (glms_vec3_dot(dir, hit->n) < 0.0f)
    push = -push;
  Ray r = {.o = glms_vec3_add(hit->p, glms_vec3_scale(hit->n, push)), .d = dir};
  return r;
  /* STUB: return (Ray){.o = hit->p, .d = dir}; */
  /* END SOLUTION */
}

#endif
