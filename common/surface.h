/* A shape's surface described exactly, in long double: the point at
 * parameters (u, v) and its unit normal, computed from the shape's own
 * floats. Each shape's name_surface gives it (declared below from
 * SHAPE_REGISTRY, common/shapes.h); the shape conformance suite
 * (tests/test_shapes.c) aims its rays at these points and takes them as the
 * reference its hits are checked against. Not used to render.
 * docs/extending.md, "The conformance suite". */
#ifndef RT_SURFACE_H
#define RT_SURFACE_H

#include <math.h>
#include <stdbool.h>

#include "shapes.h"
#include "vec.h"

typedef struct SurfacePoint {
  long double p[3]; /* the point */
  long double n[3]; /* unit normal: the front side's (outward for a solid) */
} SurfacePoint;

/* v's components in long double. */
static inline void surface_ld(vec3s v, long double out[3])
{
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}

static inline long double surface_dot(const long double a[3], const long double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void surface_cross(const long double a[3], const long double b[3],
                                 long double out[3])
{
  long double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2],
              z = a[0] * b[1] - a[1] * b[0];
  out[0] = x;
  out[1] = y;
  out[2] = z;
}

/* v scaled to length 1 (v non-zero). */
static inline void surface_normalize(long double v[3])
{
  long double len = sqrtl(surface_dot(v, v));
  for (int a = 0; a < 3; a++)
    v[a] /= len;
}

/* Two unit vectors t1, t2 with (t1, t2, n) orthonormal, for unit n. */
static inline void surface_basis(const long double n[3], long double t1[3], long double t2[3])
{
  /* The axis least aligned with n, crossed with n. */
  long double e[3] = {0, 0, 0};
  int a = fabsl(n[0]) <= fabsl(n[1]) ? 0 : 1;
  a = fabsl(n[2]) < fabsl(n[a]) ? 2 : a;
  e[a] = 1;
  surface_cross(n, e, t1);
  surface_normalize(t1);
  surface_cross(n, t1, t2);
}

/* Two unit float vectors perpendicular to unit `axis` and to each other
 * (the examples' frames). */
static inline void surface_frame(vec3s axis, vec3s *t1, vec3s *t2)
{
  long double n[3], a[3], b[3];
  surface_ld(axis, n);
  surface_normalize(n);
  surface_basis(n, a, b);
  *t1 = vec_make((float)a[0], (float)a[1], (float)a[2]);
  *t2 = vec_make((float)b[0], (float)b[1], (float)b[2]);
}

/* For each shape of the registry, its example and its surface: a shape of
 * that size around `at` facing `axis` (sphere_example, ...), and the point
 * and unit normal at parameters (u, v), false for (u, v) past an edge
 * (sphere_surface, ...). The definitions say what each draws. */
#define SURFACE_OF_(NAME, name, Type, STORE, DOC)                                    \
  Type name##_example(vec3s at, float size, vec3s axis);                             \
  bool name##_surface(const Type *shape, long double u, long double v, SurfacePoint *sp);
SHAPE_REGISTRY(SURFACE_OF_)
#undef SURFACE_OF_

#endif
