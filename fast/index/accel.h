/* Acceleration structure for the scene queries (docs/performance.md): a
 * bounding volume hierarchy over the lit spheres, the other instances in a
 * list, and for small scenes the spheres' cones seen from the eye and the
 * lights (index/cones.c). It only chooses which instances a ray is tested against; every test
 * is the shape's own function (scene_instance_hit_t: the student's
 * sphere_hit_t, plane_hit_t). */
#ifndef RT_ACCEL_H
#define RT_ACCEL_H

#include "scene.h"

/* Build scene->index (replacing any). The environment variable RT_ACCEL
 * chooses the layout for measurements: "loop" (no index: scene.c's plain loop
 * over the instances), "flat" (the spheres in one leaf, behind one bounding
 * box, no cones), "bvh" (always a hierarchy); unset, the hierarchy is built
 * from ACCEL_FLAT_MAX + 1 spheres on, and up to ACCEL_FLAT_MAX the one leaf
 * with the cones. Answers are identical whatever the layout.
 * False (one line printed) when out of memory. */
bool accel_build(Scene *scene);

enum { ACCEL_FLAT_MAX = 16 };

/* True when no lit shape can stop a shadow ray ray_spawn(hit, l) toward any
 * point of the parallelogram q on the front side of hit->n: scene_occluded
 * would then answer false for every one of them. A conservative test of the
 * shapes against the hull of hit->p and q (fast/index/hull.c), through the
 * hierarchy's boxes when there is one; false when unsure. */
bool accel_quad_unoccluded(const Scene *scene, const Hit *hit, const Quad *q);

/* The lit shapes that may stop such a shadow ray (the same test, shape by
 * shape): their instance indices in ids[0 .. count-1] and their count, or -1
 * when more than `max` may (ids then holds some of them). Every other lit
 * shape lets every such ray pass: scene_occluded over ids alone answers as
 * over the whole scene. */
int accel_quad_occluders(const Scene *scene, const Hit *hit, const Quad *q, int *ids, int max);

#endif
