/* The kinds of shape, one line each in SHAPE_REGISTRY below, and the
 * instance that pairs a shape with a material or a light (the lecture's
 * object instances). ShapeType, the Instance's union, the prototypes of each
 * shape's box and surface (box.h, surface.h), the scene's dispatch
 * (scene.c), the tests' comparisons and the shape conformance suite
 * (tests/test_shapes.c) are all written from the registry, so a new shape is
 * its own files and one line here. docs/extending.md, "Adding a shape". */
#ifndef RT_SHAPES_H
#define RT_SHAPES_H

#include "disc.h"
#include "plane.h"
#include "quad.h"
#include "sphere.h"

/* X(NAME, name, Type, STORE, DOC), one per shape, in ShapeType's order:
 *   SHAPE_NAME is its ShapeType; `name` its word (the statement's, which
 *   --trace prints) and the prefix of its functions, which the registry
 *   calls by these names (a missing one fails the build):
 *     float name_hit_t(const Type *, Ray, float tmax)      name.h
 *     void  name_hit_fill(const Type *, Ray, float t, Hit *)
 *     Box   name_bounds(const Type *)                       box.h
 *     Type  name_example(vec3s at, float size, vec3s axis)  surface.h
 *     bool  name_surface(const Type *, long double u, long double v, SurfacePoint *)
 *   (the last three are declared from this list, in the header named);
 *   STORE: INPLACE for a shape the instance holds (every lit shape), KEPT
 *   for one it points to, which another part of the scene holds (the quad:
 *   its area light's, Scene.lights[light].quad);
 *   DOC: where its hit functions are explained (the conformance suite's
 *   messages cite it). */
#define SHAPE_REGISTRY(X)                                                                       \
  X(SPHERE, sphere, Sphere, INPLACE, "docs/02-intersection.md, \"What you write\"")     \
  X(PLANE, plane, Plane, INPLACE, "docs/02-intersection.md, \"What you write\"")        \
  X(QUAD, quad, Quad, KEPT, "docs/08-area-lights.md, \"The light\"")                      \
  X(DISC, disc, Disc, INPLACE, "docs/scene-format.md, \"Statements\"")

/* The instance's member for a shape, and a pointer to its shape. */
#define SHAPE_MEMBER_INPLACE(Type, name) Type name;
#define SHAPE_MEMBER_KEPT(Type, name) const Type *name;
#define SHAPE_OF_INPLACE(inst, name) (&(inst)->name)
#define SHAPE_OF_KEPT(inst, name) ((inst)->name)
#define SHAPE_OF(inst, name, STORE) SHAPE_OF_##STORE(inst, name)

/* The kinds of shape an instance may be: SHAPE_SPHERE, SHAPE_PLANE,
 * SHAPE_QUAD, SHAPE_DISC, ... */
#define SHAPE_ENUM_(NAME, name, Type, STORE, DOC) SHAPE_##NAME,
typedef enum ShapeType { SHAPE_REGISTRY(SHAPE_ENUM_) SHAPE_COUNT } ShapeType;
#undef SHAPE_ENUM_

/* A shape paired with a material or a light. The instance holds its shape
 * (INPLACE), except an area light's quad, which it points to (KEPT:
 * Scene.lights[light].quad). The member is named as the shape. */
#define SHAPE_MEMBER_(NAME, name, Type, STORE, DOC) SHAPE_MEMBER_##STORE(Type, name)
typedef struct Instance {
  ShapeType shape;
  int material;         /* index into Scene.materials, or -1 for a light's shape */
  int light;            /* index into Scene.lights, or -1 for a lit object */
  union {
    SHAPE_REGISTRY(SHAPE_MEMBER_)
  };
} Instance;
#undef SHAPE_MEMBER_

#endif
