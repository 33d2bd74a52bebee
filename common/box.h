/* Axis-aligned bounding box (min and max corners) of a shape: what the speed
 * pack's index builds over (fast/index/). Every shape gives one through its
 * name_bounds, declared here from SHAPE_REGISTRY (common/shapes.h); an
 * unbounded shape (the plane) has infinite corners along the axes it extends
 * in. docs/extending.md, "Adding a shape". */
#ifndef RT_BOX_H
#define RT_BOX_H

#include <stdbool.h>
#include "shapes.h"
#include "vec.h"

typedef struct Box {
  vec3s min, max; /* min.x <= max.x, ...; +-INFINITY where unbounded */
} Box;

/* The margin a shape's box adds around the shape itself, for the rounding of
 * its hit test and of the box test: 2^-16 of the shape's size and 2^-20 of
 * its coordinates' magnitude (so that a grazing ray the hit test accepts is
 * never culled by the box). `size` is the shape's radius or half extent,
 * `magnitude` the largest absolute coordinate of its points. */
static inline float box_margin(float size, float magnitude)
{
  return 0x1p-16f * size + 0x1p-20f * magnitude;
}

/* The box around `centre` reaching `half` (per axis) on each side, grown by
 * `pad` on every side. */
static inline Box box_around(vec3s centre, vec3s half, float pad)
{
  vec3s h = glms_vec3_adds(half, pad);
  return (Box){glms_vec3_sub(centre, h), glms_vec3_add(centre, h)};
}

/* The smallest box holding a and b. */
static inline Box box_union(Box a, Box b)
{
  return (Box){glms_vec3_minv(a.min, b.min), glms_vec3_maxv(a.max, b.max)};
}

/* True when every corner coordinate is finite. */
static inline bool box_is_bounded(Box b)
{
  return vec_is_finite(b.min) && vec_is_finite(b.max);
}

/* True when p lies in b (faces included). */
static inline bool box_holds(Box b, vec3s p)
{
  return p.x >= b.min.x && p.x <= b.max.x && p.y >= b.min.y && p.y <= b.max.y &&
         p.z >= b.min.z && p.z <= b.max.z;
}

/* Each shape's box, padded by box_margin: sphere_bounds, plane_bounds, ...
 * (their definitions say how each is drawn). */
#define BOX_BOUNDS_(NAME, name, Type, STORE, DOC) Box name##_bounds(const Type *shape);
SHAPE_REGISTRY(BOX_BOUNDS_)
#undef BOX_BOUNDS_

#endif
