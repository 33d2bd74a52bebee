/* Light.Radiance with shadows (steps 04 and 05; common/shadow.h): the
 * radiance a point or directional light sends to a hit point, zero when
 * something lies between. docs/05-shadows.md. */
#include "shadow.h"

#include "scene.h"

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
