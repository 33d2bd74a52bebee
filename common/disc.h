/* Disc (centre, unit normal, radius): a round, flat shape of the scene file
 * (`disc` statement), given, not written by the student: the ray meets the
 * disc's plane as in step 02's plane_hit_t, within `radius` of the centre.
 * docs/scene-format.md, "Statements"; docs/extending.md shows how a shape is
 * added. */
#ifndef RT_DISC_H
#define RT_DISC_H

#include "ray.h"

typedef struct Disc {
  vec3s center;
  vec3s normal; /* unit */
  float radius; /* > 0 */
} Disc;

/* The disc of that centre, normal (any non-zero length) and radius. */
Disc disc_make(vec3s center, vec3s normal, float radius);

/* Distance to the intersection with t in (0, tmax), or INFINITY (also for a
 * ray parallel to the disc). Both sides are hit; a point exactly `radius`
 * from the centre is on the disc. */
float disc_hit_t(const Disc *d, Ray r, float tmax);

/* Fill the hit at distance t: p snapped onto the disc's plane, n facing the
 * ray, backface when the ray comes from the side the normal points to not. */
void disc_hit_fill(const Disc *d, Ray r, float t, Hit *hit);

#endif
