/* Point and directional lights (step 04). docs/04-phong.md. */
#include "light.h"

vec3s light_incident(const Light *light, vec3s p, float min_dist, vec3s *l,
                     float *dist)
{
  /* BEGIN SOLUTION step 04 */
  if (light->type == LIGHT_DIRECTIONAL) {
    /* No fall-off: every point receives E from -direction. */
    *l = glms_vec3_negate(light->direction);
    *dist = INFINITY;
    return light->irradiance;
  }
  if (light->type == LIGHT_POINT) {
    vec3s to_light = glms_vec3_sub(light->position, p);
    float r2 = glms_vec3_dot(to_light, to_light);
    float r = sqrtf(r2);
    if (r > min_dist) {
      *l = glms_vec3_scale(to_light, 1.0f / r);
      *dist = r;
      return glms_vec3_divs(light->power, r2); /* L_i = P / r^2 */
    }
  }
  /* END SOLUTION */
  /* A point light at the shaded point (no direction) or an area light. */
  *l = glms_vec3_zero();
  *dist = 0.0f;
  return glms_vec3_zero();
}
