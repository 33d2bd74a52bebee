/* Shading of step 06: step 05's, with ambient light and the point lights'
 * spheres seen by the camera. docs/06-ambient.md. */
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

/* Phong with ambient: the colour the hit point sends toward `eye`, m_amb l_amb
 * plus every light's term. */
vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye, RenderCtx *ctx);

/* The colour seen along `ray`: a point light's sphere shows P / t^2, the
 * background when it hits nothing. */
vec3s shade_trace(const Scene *scene, Ray ray, RenderCtx *ctx);

#endif
