/* Parallelogram corner + a edge1 + b edge2, a, b in [0, 1]: the shape of an
 * area light (step 08, docs/08-area-lights.md). One-sided: it faces
 * normalize(edge1 x edge2). */
#ifndef RT_QUAD_H
#define RT_QUAD_H

#include "ray.h"

typedef struct Quad {
  vec3s corner, edge1, edge2;
  vec3s normal; /* unit, edge1 x edge2 direction */
  float area;   /* |edge1 x edge2| */
} Quad;

/* The parallelogram; edges must not be parallel (area > 0). When the area
 * comes out 0 in float, the normal is 0 (the parser refuses such a light). */
Quad quad_make(vec3s corner, vec3s edge1, vec3s edge2);

/* Distance to the intersection with t in (0, tmax), or INFINITY. Both sides
 * are hit; hit_fill tells which through `backface`. */
float quad_hit_t(const Quad *q, Ray r, float tmax);

/* Fill the hit at distance t (n facing the ray, backface = behind the front). */
void quad_hit_fill(const Quad *q, Ray r, float t, Hit *hit);

/* The hit of a ray meeting, at distance t, a flat shape (a quad, a disc)
 * whose plane passes through `point` with unit `normal`: the point projected
 * back onto the plane, n facing the ray, backface = behind the front. */
void flat_hit_fill(vec3s point, vec3s normal, Ray r, float t, Hit *hit);

/* The point at parameters (a, b) in [0,1]^2. */
vec3s quad_point(const Quad *q, float a, float b);

#endif
