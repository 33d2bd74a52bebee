/* Sphere (c, r) and the ray-sphere intersection of step 02.
 * docs/02-intersection.md derives it; docs/accuracy.md explains the stable form. */
#ifndef RT_SPHERE_H
#define RT_SPHERE_H

#include "ray.h"

typedef struct Sphere {
  vec3s center;
  float radius; /* > 0 */
} Sphere;

/* Distance to the nearest intersection with t in (0, tmax), or INFINITY when
 * there is none. A ray starting inside the sphere hits its far side. */
float sphere_hit_t(const Sphere *s, Ray r, float tmax);

/* Fill p (refined onto the sphere), n (facing against the ray), backface and
 * p_err for the hit at distance t found by sphere_hit_t. */
void sphere_hit_fill(const Sphere *s, Ray r, float t, Hit *hit);

#endif
