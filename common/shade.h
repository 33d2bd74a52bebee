/* Shading (steps 04 to 08): the lecture's Scene.TraceRay and
 * PhongMaterial.Eval, which call Phong's term (phong.h), Light.Radiance
 * (shadow.h) and the area lights (area_light.h), each written once. A later
 * step adds to an earlier function where the lecture does (shadows at 05,
 * ambient and the lights the camera sees at 06, area lights at 08); a step's
 * program loads its scene with its own SceneFeature bits (scene.h), so an
 * earlier step never meets what a later one adds. docs/04-phong.md to
 * docs/08-area-lights.md. */
#ifndef RT_SHADE_H
#define RT_SHADE_H

#include "ray.h"

typedef struct Scene Scene; /* scene.h */
typedef struct Film Film;   /* film.h */

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
