/* Shading of step 05: the lecture's Scene.TraceRay, PhongMaterial.Eval and
 * Light.Radiance with its shadow test. docs/05-shadows.md. */
#ifndef RT_SHADE_H
#define RT_SHADE_H

#include "render.h"

/* Radiance arriving at the hit point from `light`, and the unit direction `l`
 * toward it: zero when something lies between the point and the light. */
vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit,
                     vec3s *l, RenderCtx *ctx);

/* Phong: the colour the hit point sends toward `eye`. */
vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye, RenderCtx *ctx);

/* The colour seen along `ray` (the background when it hits nothing). */
vec3s shade_trace(const Scene *scene, Ray ray, RenderCtx *ctx);

#endif
