/* Shading of step 06: the lecture's Scene.TraceRay (lights seen by the camera),
 * PhongMaterial.Eval (with ambient) and Light.Radiance. docs/06-ambient.md. */
#ifndef RT_SHADE_H
#define RT_SHADE_H

#include "render.h"

/* Radiance arriving at the hit point from `light`, and the unit direction `l`
 * toward it: zero when something lies between the point and the light. */
vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit,
                     vec3s *l, RenderCtx *ctx);

/* Phong with ambient: the colour the hit point sends toward `eye`. */
vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye, RenderCtx *ctx);

/* The colour seen along `ray`: a light's own colour when it hits a light's
 * shape, the background when it hits nothing. */
vec3s shade_trace(const Scene *scene, Ray ray, RenderCtx *ctx);

#endif
