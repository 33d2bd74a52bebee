/* Shading of step 08: the lecture's Scene.TraceRay (area lights seen by the
 * camera), PhongMaterial.Eval and Light.Radiance, with area lights sampled as
 * N point lights. docs/08-area-lights.md. */
#ifndef RT_SHADE_H
#define RT_SHADE_H

#include "render.h"

/* Radiance arriving at the hit point from `light`, and the unit direction `l`
 * toward it: zero when something lies between the point and the light. */
vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit,
                     vec3s *l, RenderCtx *ctx);

/* Phong's contribution of area light `light_index` at the hit point seen from
 * `eye`: the sum over ctx->set->light_samples samples x_k on the light, each a
 * point light of power (P/N) cos(theta_light) (zero when the point is behind
 * the light) that counts only when nothing lies between. The samples follow
 * ctx->set->sampler's pattern, keyed by seed, light, pixel and camera sample;
 * with ctx->set->adaptive > 0 shadow rays to the light's four corners come
 * first, and the samples skip theirs when the four agree; without it, a point
 * no lit shape can shadow (scene_quad_unoccluded) skips them all. Shadow rays
 * are counted in ctx->rays. */
vec3s shade_area(const Scene *scene, int light_index, const Hit *hit, vec3s eye,
                 RenderCtx *ctx);

/* Phong with ambient: the colour the hit point sends toward `eye`. */
vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye, RenderCtx *ctx);

/* The colour seen along `ray`: a light's own colour when it hits a light's
 * shape (an area light: L = P / A on its front face, black behind), the
 * background when it hits nothing. */
vec3s shade_trace(const Scene *scene, Ray ray, RenderCtx *ctx);

#endif
