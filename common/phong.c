/* Phong's reflection of one light (step 04; common/phong.h): the term
 * PhongMaterial.Eval adds for each light. docs/04-phong.md. */
#include "phong.h"

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
