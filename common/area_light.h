/* Area lights (step 08): a parallelogram light as scene->light_samples
 * point lights spread over it, each checked for shadow.
 * docs/08-area-lights.md. */
#ifndef RT_AREA_LIGHT_H
#define RT_AREA_LIGHT_H

#include "ray.h"

typedef struct Scene Scene; /* scene.h */

/* Area light `light_index` at the hit point seen from the unit direction v
 * (step 08): the sum of shade_phong_light over scene->light_samples points
 * x_k on the light, each a point light of power (P/n) cos(theta_light) (zero
 * when the hit point is behind the light) that counts only when nothing lies
 * between (shade_visible). The points follow scene->sampler's pattern, keyed
 * by the seed, the light and the hit point (docs/08-area-lights.md). */
vec3s shade_area(const Scene *scene, int light_index, const Hit *hit, vec3s v);

#endif
