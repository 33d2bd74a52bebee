/* Shading (steps 04 to 08): the lecture's Scene.TraceRay, PhongMaterial.Eval
 * and Light.Radiance, each written once. A later step adds to an earlier
 * function where the lecture does (shadows at 05, ambient and the lights the
 * camera sees at 06, area lights at 08); a step's program loads its scene
 * with its own SceneFeature bits (scene.h), so an earlier step never meets
 * what a later one adds. docs/04-phong.md to docs/08-area-lights.md. */
#ifndef RT_SHADE_H
#define RT_SHADE_H

#include "light.h"
#include "material.h"
#include "ray.h"

typedef struct Scene Scene; /* scene.h */
typedef struct Film Film;   /* film.h */

/* Phong's term for one light (step 04): what the hit point, of material m,
 * sends toward the unit direction v (toward the eye) for radiance li
 * arriving from the unit direction l: li (m_dif (n.l) + m_spe
 * max(0, r.v)^shininess), r = l mirrored about n; zero when n.l <= 0. */
vec3s shade_phong_light(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l);

/* Visibility (step 05): true when nothing lies between the hit point and the
 * point at distance `dist` from it in the unit direction `l`. */
bool shade_visible(const Scene *scene, const Hit *hit, vec3s l, float dist);

/* Light.Radiance: the radiance arriving at the hit point from a point or
 * directional light, and the unit direction *l toward it (light_incident,
 * step 04); from step 05, zero when something lies between (shade_visible). */
vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit, vec3s *l);

/* Area light `light_index` at the hit point seen from the unit direction v
 * (step 08): the sum of shade_phong_light over scene->light_samples points
 * x_k on the light, each a point light of power (P/n) cos(theta_light) (zero
 * when the hit point is behind the light) that counts only when nothing lies
 * between (shade_visible). The points follow scene->sampler's pattern, keyed
 * by the seed, the light and the hit point (docs/08-area-lights.md). */
vec3s shade_area(const Scene *scene, int light_index, const Hit *hit, vec3s v);

/* PhongMaterial.Eval: the colour the hit point sends toward `eye`: every
 * light's term (step 04), plus m_amb l_amb from step 06. */
vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye);

/* Scene.TraceRay: the colour seen along `ray`, the background when it hits
 * nothing; from step 06 a point light's sphere shows P / t^2, from step 08
 * an area light L = P / A on its front face and black behind. */
vec3s shade_trace(const Scene *scene, Ray ray);

/* Render's body for one camera sample: the colour seen through the film
 * point (x, y) in [0,1]^2 (0 the left and bottom edges): the camera's ray
 * there, traced. */
vec3s shade_sample(const Scene *scene, float x, float y);

/* Render's body for one pixel (steps 04 to 06): shade_sample at pixel
 * (i, j)'s centre (film_sample). */
vec3s shade_pixel(const Scene *scene, const Film *film, int i, int j);

#endif
