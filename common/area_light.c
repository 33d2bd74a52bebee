/* Area lights (step 08; common/area_light.h): a parallelogram light as
 * scene->light_samples point lights spread over it, each checked for
 * shadow. docs/08-area-lights.md. */
#include "area_light.h"

#include "phong.h"
#include "scene.h"
#include "shadow.h"

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
  const Material *m = &scene->materials[hit->material];
  int n = scene->light_samples;
  SamplerPattern pattern = sampler_pattern_at(scene->sampler.kind, scene->sampler.seed,
                                              (uint32_t)light_index, hit->p, (uint32_t)n);
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
