/* Scene.TraceRay and PhongMaterial.Eval (steps 04, 06 and 08;
 * common/shade.h): the colour seen along a ray, a light's term and the
 * ambient term at its hit point, and Render's body for a film point and a
 * pixel. docs/04-phong.md, docs/06-ambient.md, docs/08-area-lights.md. */
#include "shade.h"

#include "area_light.h"
#include "film.h"
#include "phong.h"
#include "scene.h"
#include "shadow.h"

/* One light's term at the hit point seen from the direction v. */
static vec3s shade_light(const Scene *scene, int k, const Hit *hit, vec3s v)
{
  /* BEGIN SOLUTION step 08 */
  /* HINT: complete shade_light: an area light's term is shade_area's */
  if (scene->lights[k].type == LIGHT_AREA)
    return shade_area(scene, k, hit, v);
  /* END SOLUTION */
  vec3s l;
  vec3s li = shade_incident(scene, &scene->lights[k], hit, &l);
  return shade_phong_light(&scene->materials[hit->material], hit, v, li, l);
}

vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye)
{
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 06 */
  /* HINT: complete shade_phong: the ambient term m_amb l_amb */
  /* m_amb * l_amb: skipped when the scene has no ambient light at all. */
  if (scene->info.ambient)
    c = glms_vec3_mul(scene->materials[hit->material].ambient, scene->ambient);
  /* END SOLUTION */
  /* BEGIN SOLUTION step 04 */
  vec3s v = glms_vec3_normalize(glms_vec3_sub(eye, hit->p));
  for (int k = 0; k < scene->n_lights; k++)
    c = glms_vec3_add(c, shade_light(scene, k, hit, v));
  /* END SOLUTION */
  return c;
}

vec3s shade_trace(const Scene *scene, Ray ray)
{
  Hit hit;
  if (!scene_intersect(scene, ray, INFINITY, &hit))
    return scene->background;
  /* BEGIN SOLUTION step 08 */
  /* HINT: complete shade_trace: an area light shows P / A in front, black behind */
  if (hit.light >= 0 && scene->lights[hit.light].type == LIGHT_AREA) {
    /* The front face shows the radiance L = P / A; the light is one-sided and
     * its back emits nothing: black (docs/08-area-lights.md). */
    const Light *area = &scene->lights[hit.light];
    return hit.backface ? glms_vec3_zero() : glms_vec3_divs(area->power, area->quad.area);
  }
  /* END SOLUTION */
  /* BEGIN SOLUTION step 06 */
  /* HINT: complete shade_trace: a point light's sphere shows P / t^2 */
  if (hit.light >= 0) {
    /* A point light's sphere shows the radiance P / t^2 it sends this far. */
    const Light *light = &scene->lights[hit.light];
    return glms_vec3_divs(light->power, hit.t * hit.t);
  }
  /* STUB: if (hit.light >= 0) return glms_vec3_zero(); */
  /* END SOLUTION */
  return shade_phong(scene, &hit, ray.o);
}

vec3s shade_sample(const Scene *scene, float x, float y)
{
  return shade_trace(scene, camera_ray(&scene->camera, x, y));
}

vec3s shade_pixel(const Scene *scene, const Film *film, int i, int j)
{
  vec2s s = film_sample(film, i, j);
  return shade_sample(scene, s.x, s.y);
}
