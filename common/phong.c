/* PhongMaterial.Eval (steps 04, 06 and 08; common/shade.h): the colour a
 * hit point sends toward the eye, a term per light plus the ambient term.
 * docs/04-phong.md, docs/06-ambient.md, docs/08-area-lights.md. */
#include "shade.h"

#include "scene.h"

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
