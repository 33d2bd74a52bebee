/* Acceleration structure for the scene queries (docs/performance.md): a
 * bounding volume hierarchy over the lit spheres, the other instances in a
 * list, and for small scenes the spheres' cones seen from the eye and the
 * lights (index/cones.c). It only chooses which instances a ray is tested against; every test
 * is the shape's own function (scene_instance_hit_t: the student's
 * sphere_hit_t, plane_hit_t). */
#ifndef RT_ACCEL_H
#define RT_ACCEL_H

#include "scene.h"
#include "scene_index.h"

/* Point scene->index at a new index's query table (freeing the one
 * accel_build made before, if any). The environment variable RT_ACCEL
 * chooses the layout for measurements: "loop" (no index: scene.c's plain loop
 * over the instances), "flat" (the spheres in one leaf, behind one bounding
 * box, no cones), "bvh" (always a hierarchy); unset, the hierarchy is built
 * from ACCEL_FLAT_MAX + 1 spheres on, and up to ACCEL_FLAT_MAX the one leaf
 * with the cones. With more than 4 light samples, the any-hit query
 * recognises the shadow rays toward an area light by their end and tests
 * only the shapes that may stand between their origin and the light
 * (index/hull.c). Answers are identical whatever the layout.
 * False (one line printed) when out of memory. */
bool accel_build(Scene *scene);

/* Free the index accel_build made for scene; scene->index becomes NULL. */
void accel_free(Scene *scene);

enum { ACCEL_FLAT_MAX = 16 };

/* The lit shapes that may stop a ray from o to a point of the quad q, as
 * the any-hit query finds them for the shadow rays toward an area light:
 * their count (instance indices in ids), or -1 when more than max may. For
 * the tests; scene->index must be accel_build's. */
int accel_area_shapes(const Scene *scene, vec3s o, const Quad *q, int *ids, int max);

#endif
