/* Which spheres of a small scene a ray may meet, from the cones they fill
 * (docs/performance.md, "Cones from the eye and the lights"): seen from the
 * eye and from each point light, each sphere fills a cone of directions;
 * across a directional light, a disc. A ray the cones know (a camera ray
 * leaving the eye, a shadow ray ending at a point light or running along a
 * directional light) is compared with all of them at once, and tested only
 * against the spheres it may meet; every test is still the shape's own
 * function. */
#ifndef RT_ACCEL_CONES_H
#define RT_ACCEL_CONES_H

#include <stdint.h>

#include "scene.h"
#include "scene_index.h"

typedef struct Cones Cones;

/* The margin every culling test adds to a sphere's radius (the hierarchy's
 * boxes; the cones take twice it): a relative 2^-16 of the radius and 2^-20
 * of the coordinates' magnitude, so that a grazing ray sphere_hit_t accepts
 * is never culled. */
static inline float sphere_pad(const Sphere *s)
{
  return 0x1p-16f * s->radius + 0x1p-20f * (vec_max_abs(s->center) + s->radius);
}

/* The cones of the lit shapes ids[0 .. n), 1 <= n <= CONES_MAX, listed in
 * increasing instance order, each within the sphere bounds[k] (a sphere
 * itself, another shape the ball around its box), for scene->camera's eye
 * and the scene's point and directional lights; NULL when none could be
 * built (the caller then goes without). */
enum { CONES_MAX = 16 };
Cones *cones_build(const Scene *scene, const int *ids, const Sphere *bounds, int n);
void cones_free(Cones *c);

/* The instance indices given to cones_build, in its order. */
const int *cones_spheres(const Cones *c);

/* A ray leaving the eye: true, with bit k of *mask set for each sphere
 * cones_spheres(g)[k] it may meet (none of the others can be at any t > 0).
 * False when the ray is not one the cones know (origin not the eye). */
bool cones_from_eye(const Cones *c, const Ray *r, uint32_t *mask);

/* A shadow ray whose end o + tmax d is within the build's margin of a point
 * light, or whose direction is exactly -direction of a directional light:
 * true, with the spheres that may meet it for t in (0, tmax) in *mask, as
 * above. False when the ray is neither. */
bool cones_toward_light(const Cones *c, const Ray *r, float tmax, uint32_t *mask);

#endif
