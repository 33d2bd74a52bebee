/* Shading (steps 04 to 08; common/shade.h): Scene.TraceRay,
 * PhongMaterial.Eval and Light.Radiance. docs/04-phong.md to
 * docs/08-area-lights.md. */
#include "shade.h"

#include <string.h>
#include "film.h"
#include "rng.h"
#include "sampler.h"
#include "scene.h"
#include "shapes.h"

vec3s shade_phong_light(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l)
{
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 04 */
  float n_dot_l = glms_vec3_dot(hit->n, l);
  if (!(n_dot_l > 0.0f)) /* light behind the surface: no diffuse, no specular */
    return c;
  c = glms_vec3_scale(glms_vec3_mul(m->diffuse, li), n_dot_l);
  if (!vec_is_zero(m->specular)) { /* no lobe to compute without a specular colour */
    /* The lecture's slide omits L_i here; without it the highlight would not
     * dim with distance or light power (docs/04-phong.md). */
    vec3s r = vec_reflect(glms_vec3_negate(l), hit->n);
    float lobe = powf(fmaxf(0.0f, glms_vec3_dot(r, v)), m->shininess);
    c = glms_vec3_add(c, glms_vec3_scale(glms_vec3_mul(m->specular, li), lobe));
  }
  /* END SOLUTION */
  return c;
}

bool shade_visible(const Scene *scene, const Hit *hit, vec3s l, float dist)
{
  /* BEGIN SOLUTION step 05 */
  /* The lecture traces a closest-hit ray and checks that it reaches the light.
   * Any occluder closer than the light will do, so ask the cheaper any-hit
   * query, stopping just short of the light. The origin is pushed off the
   * surface by its error bound, not by a fixed epsilon (docs/05-shadows.md). */
  return !scene_occluded(scene, ray_spawn(hit, l), ray_shadow_tmax(dist));
  /* STUB: return true; */
  /* END SOLUTION */
}

vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit, vec3s *l)
{
  float dist;
  vec3s li = light_incident(light, hit->p, hit->p_err, l, &dist);
  /* Shadows from step 05 on (a scene loaded without them has none). A light
   * behind the surface adds nothing (shade_phong_light skips it): it needs
   * no shadow ray. */
  if (scene->info.shadows && glms_vec3_dot(hit->n, *l) > 0.0f &&
      !shade_visible(scene, hit, *l, dist))
    li = glms_vec3_zero();
  return li;
}

/* Where the n samples of area light `light` go for this hit point: the
 * scene's pattern (--sampler) on the light's parameters (a, b) in [0,1)^2,
 * keyed by the seed, the light and the hit point's coordinates (their bits):
 * each camera sample's hit point draws a pattern of its own, the same
 * whichever thread traces it. */
static SamplerPattern light_pattern(const Scene *scene, int light, const Hit *hit, int n)
{
  uint32_t b[3];
  memcpy(b, &hit->p, sizeof b);
  Rng r = rng_make(scene->sampler.seed ^ (0x9e3779b9u * (uint32_t)(light + 1)),
                   b[0] ^ (b[2] * 0x85ebca77u), b[1]);
  uint32_t pixel = rng_next(&r);
  uint32_t seed = rng_next(&r);
  return sampler_pattern(scene->sampler.kind, seed, pixel, (uint32_t)n);
}

/* BEGIN SOLUTION step 08 */
/* The light's point (a, b) as a point light of power (P/n) cos(theta_light):
 * its radiance at the hit point, *l toward it and *dist to it. Zero when the
 * hit point is behind the light (one-sided) or on it. */
static vec3s area_incident(const Light *light, vec2s ab, int n, const Hit *hit, vec3s *l,
                           float *dist)
{
  vec3s to_x = glms_vec3_sub(quad_point(&light->quad, ab.x, ab.y), hit->p);
  float r2 = glms_vec3_dot(to_x, to_x);
  *dist = sqrtf(r2);
  if (!(*dist > hit->p_err))
    return glms_vec3_zero();
  *l = glms_vec3_scale(to_x, 1.0f / *dist);
  float cos_light = -glms_vec3_dot(*l, light->quad.normal);
  if (!(cos_light > 0.0f))
    return glms_vec3_zero();
  return glms_vec3_scale(light->power, cos_light / ((float)n * r2));
}
/* END SOLUTION */

vec3s shade_area(const Scene *scene, int light_index, const Hit *hit, vec3s v)
{
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 08 */
  const Light *light = &scene->lights[light_index];
  const Material *m = &scene->materials[hit->inst->material];
  int n = scene->light_samples;
  SamplerPattern pattern = light_pattern(scene, light_index, hit, n);
  for (int k = 0; k < n; k++) {
    vec3s l;
    float dist;
    vec2s ab = sampler_point(&pattern, (uint32_t)k);
    vec3s li = area_incident(light, ab, n, hit, &l, &dist);
    /* A sample that adds nothing needs no shadow ray. */
    if (vec_is_zero(li) || !(glms_vec3_dot(hit->n, l) > 0.0f))
      continue;
    if (shade_visible(scene, hit, l, dist))
      c = glms_vec3_add(c, shade_phong_light(m, hit, v, li, l));
  }
  /* END SOLUTION */
  return c;
}

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
  return shade_phong_light(&scene->materials[hit->inst->material], hit, v, li, l);
}

vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye)
{
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 06 */
  /* HINT: complete shade_phong: the ambient term m_amb l_amb */
  /* m_amb * l_amb: skipped when the scene has no ambient light at all. */
  if (scene->info.ambient)
    c = glms_vec3_mul(scene->materials[hit->inst->material].ambient, scene->ambient);
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
  if (hit.inst->light >= 0 && scene->lights[hit.inst->light].type == LIGHT_AREA) {
    /* The front face shows the radiance L = P / A; the light is one-sided and
     * its back emits nothing: black (docs/08-area-lights.md). */
    const Light *area = &scene->lights[hit.inst->light];
    return hit.backface ? glms_vec3_zero() : glms_vec3_divs(area->power, area->quad.area);
  }
  /* END SOLUTION */
  /* BEGIN SOLUTION step 06 */
  /* HINT: complete shade_trace: a point light's sphere shows P / t^2 */
  if (hit.inst->light >= 0) {
    /* A point light's sphere shows the radiance P / t^2 it sends this far. */
    const Light *light = &scene->lights[hit.inst->light];
    return glms_vec3_divs(light->power, hit.t * hit.t);
  }
  /* STUB: if (hit.inst->light >= 0) return glms_vec3_zero(); */
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
