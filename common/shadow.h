/* Light.Radiance with shadows (steps 04 and 05): what a point or
 * directional light sends to a hit point, zero when something lies between.
 * docs/05-shadows.md. */
#ifndef RT_SHADOW_H
#define RT_SHADOW_H

#include <stdbool.h>
#include "light.h"
#include "ray.h"

typedef struct Scene Scene; /* scene.h */

/* Visibility (step 05): true when nothing lies between the hit point and the
 * point at distance `dist` from it in the unit direction `l`. */
bool shade_visible(const Scene *scene, const Hit *hit, vec3s l, float dist);

/* Light.Radiance: the radiance arriving at the hit point from a point or
 * directional light, and the unit direction *l toward it (light_incident,
 * step 04); from step 05, zero when something lies between (shade_visible). */
vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit, vec3s *l);

#endif
