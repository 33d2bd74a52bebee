/* The registry of shapes: one line per kind of shape in SHAPE_REGISTRY
 * below. The kinds an instance may be (ShapeType, the Instance's union,
 * scene.h), the scene's dispatch (scene_instance_hit_t, its hit fill, scene_instance_bounds,
 * scene_shape_name: scene.c), the tests' comparisons and the shape
 * conformance suite (tests/test_shapes.c) are all written from it, so a new
 * shape is its own files and one line here. docs/extending.md, "Adding a
 * shape". */
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
 *     float name_hit_t(const Type *, Ray, float tmax)
 *     void  name_hit_fill(const Type *, Ray, float t, Hit *)
 *     Box   name_bounds(const Type *)
 *     Type  name_example(vec3s at, float size, vec3s axis)
 *     bool  name_surface(const Type *, long double u, long double v, SurfacePoint *)
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

#endif
