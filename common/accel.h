/* Acceleration structure for the scene queries: a bounding volume hierarchy
 * over the spheres, built when a scene has enough of them to pay for it.
 * docs/performance.md. */
#ifndef RT_ACCEL_H
#define RT_ACCEL_H

#include "scene.h"

/* Build scene->accel when worthwhile (else leave it NULL: the plain loop is
 * faster on a handful of objects). False when out of memory. */
bool accel_build(Scene *scene);

/* Free scene->accel; harmless when there is none. */
void accel_free(Scene *scene);

/* Closest instance hit with t in (0, *tmax); *tmax becomes its distance.
 * NULL when none. */
const Instance *accel_closest(const Scene *scene, Ray r, float *tmax);

/* True when some lit shape lies on the ray with t in (0, tmax). */
bool accel_any(const Scene *scene, Ray r, float tmax);

#endif
