/* Infinite plane (point, unit normal) and the ray-plane intersection of step 02.
 * docs/02-intersection.md. */
#ifndef RT_PLANE_H
#define RT_PLANE_H

#include "ray.h"

typedef struct Plane {
  vec3s point;
  vec3s normal; /* unit */
  int axis;     /* 0, 1, 2 when the normal is a coordinate axis, else -1 */
} Plane;

/* The plane through `point` with normal `normal` (any non-zero length). */
Plane plane_make(vec3s point, vec3s normal);

/* Distance to the intersection with t in (0, tmax), or INFINITY (also for a
 * ray parallel to the plane). */
float plane_hit_t(const Plane *pl, Ray r, float tmax);

/* Fill the hit at distance t: p snapped onto the plane, n facing the ray. */
void plane_hit_fill(const Plane *pl, Ray r, float t, Hit *hit);

#endif
