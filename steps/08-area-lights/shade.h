/* Shading of step 08: step 07's, with parallelogram area lights sampled as N
 * point lights. docs/08-area-lights.md. */
#ifndef RT_SHADE_H
#define RT_SHADE_H

#include "app/render.h"

/* True when nothing lies between the hit point and the point at distance
 * `dist` from it in the unit direction `l` (a light there is visible). */
bool shade_visible(const Scene *scene, const Hit *hit, vec3s l, float dist, RenderCtx *ctx);

/* Radiance arriving at the hit point from `light`, and the unit direction `l`
 * toward it: zero when something lies between the point and the light. */
vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit,
                     vec3s *l, RenderCtx *ctx);

/* Phong's term for one light: what the hit point, of material m, sends toward
 * the unit direction v (toward the eye) for radiance li arriving from the unit
 * direction l: li (m_dif (n.l) + m_spe max(0, r.v)^shininess), r = l
 * mirrored about n; zero when n.l <= 0 (the light is behind the surface). */
vec3s shade_phong_light(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l);

/* Phong's contribution of area light `light_index` at the hit point, seen
 * from the unit direction v: the sum over n samples x_k on the light, each a
 * point light of power (P/n) cos(theta_light) (zero when the point is behind
 * the light) that counts only when nothing lies between (shade_visible). The
 * samples follow ctx->set->sampler's pattern, keyed by seed, light, pixel and
 * camera sample. shade_phong asks for scene->light_samples samples (with
 * the grid, a quarter of them, at least 16, where nothing can shadow the
 * light). */
vec3s shade_area(const Scene *scene, int light_index, const Hit *hit, vec3s v, int n,
                 RenderCtx *ctx);

/* Phong with ambient: the colour the hit point sends toward `eye`, m_amb l_amb
 * plus every light's term. */
vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye, RenderCtx *ctx);

/* The colour seen along `ray`: a point light's sphere shows P / t^2, an area
 * light L = P / A on its front face and black behind, the background when it
 * hits nothing. */
vec3s shade_trace(const Scene *scene, Ray ray, RenderCtx *ctx);

#endif
