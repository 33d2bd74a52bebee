/* Acceleration structure for the scene queries (docs/performance.md): a
 * bounding volume hierarchy over the lit spheres, the other instances in a
 * list. It only chooses which instances a ray is tested against; every test
 * is the shape's own function (scene_instance_hit_t: the student's
 * sphere_hit_t, plane_hit_t). */
#ifndef RT_ACCEL_H
#define RT_ACCEL_H

#include "scene.h"

/* Build scene->index (replacing any). The environment variable RT_ACCEL
 * chooses the layout for measurements: "loop" (no index: scene.c's plain loop
 * over the instances), "flat" (the spheres in one leaf, behind one bounding
 * box), "bvh" (always a hierarchy); unset, the hierarchy is built from
 * ACCEL_FLAT_MAX + 1 spheres on. Answers are identical whatever the layout.
 * False (one line printed) when out of memory. */
bool accel_build(Scene *scene);

enum { ACCEL_FLAT_MAX = 16 };

/* True when no lit shape can stop a shadow ray ray_spawn(hit, l) toward any
 * point of the parallelogram q on the front side of hit->n: scene_occluded
 * would then answer false for every one of them. A conservative test of the
 * shapes against the hull of hit->p and q (common/accel/hull.c), through the
 * hierarchy's boxes when there is one; false when unsure. */
bool accel_quad_unoccluded(const Scene *scene, const Hit *hit, const Quad *q);

#endif
