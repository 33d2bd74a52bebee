/* Acceleration structure for the scene queries: the lit spheres in blocks of
 * eight (structure of arrays, one SIMD kernel per block), under a bounding
 * volume hierarchy when there are more than a few blocks; planes and lights'
 * shapes in a plain list. docs/performance.md. */
#ifndef RT_ACCEL_H
#define RT_ACCEL_H

#include "scene.h"

struct ShadowHull;

/* Build scene->accel. The environment variable RT_ACCEL chooses the layout for
 * measurements: "loop" (none: scene.c's plain loop over instances), "flat"
 * (sphere blocks, no hierarchy), "bvh" (always a hierarchy); unset, the
 * hierarchy is built from ACCEL_FLAT_MAX spheres on. Results are identical
 * whatever the layout. False (one line printed) when out of memory. */
bool accel_build(Scene *scene);

enum { ACCEL_FLAT_MAX = 16 };

/* Free scene->accel; harmless when there is none. */
void accel_free(Scene *scene);

/* Closest instance hit with t in (0, *tmax); *tmax becomes its distance.
 * NULL when none. Same answer as testing every instance in order, keeping the
 * first of equal distances. */
const Instance *accel_closest(const Scene *scene, Ray r, float *tmax);

/* True when some lit shape lies on the ray with t in (0, tmax). */
bool accel_any(const Scene *scene, Ray r, float tmax);

/* False only when no lit shape can stop a shadow ray inside the hull
 * (common/hull.h): the blocks' spheres, through the hierarchy's boxes, and the
 * lit planes; any other lit shape counts as a possible occluder. */
bool accel_may_occlude(const Scene *scene, const struct ShadowHull *h);

/* Distance to one instance along the ray, INFINITY when missed (its shape's
 * hit_t function). */
float accel_instance_hit_t(const Instance *inst, Ray r, float tmax);

#endif
