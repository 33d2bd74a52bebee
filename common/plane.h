/* Infinite plane (point, unit normal) and the ray-plane intersection of step 02.
 * docs/02-intersection.md. */
#ifndef RT_PLANE_H
#define RT_PLANE_H

#include "box.h"
#include "surface.h"
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

/* The plane is unbounded: its box is infinite (-INFINITY to INFINITY) along
 * every axis, except a plane normal to a coordinate axis (axis >= 0), whose
 * box is flat along that axis at the plane's coordinate, padded by
 * box_margin. box_is_bounded tells the two apart from a bounded box. */
Box plane_bounds(const Plane *pl);

/* For the shape conformance suite (common/shapes.h, tests/test_shapes.c):
 * the plane through `at` with normal `axis` (`size` unused), and its surface
 * in long double (common/surface.h): point + (u - 1/2) t1 + (v - 1/2) t2,
 * (t1, t2, normal) orthonormal; on the plane for every (u, v). */
Plane plane_example(vec3s at, float size, vec3s axis);
bool plane_surface(const Plane *pl, long double u, long double v, SurfacePoint *sp);

#endif
