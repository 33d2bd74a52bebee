/* Step 05: Phong shading with shadows: a light counts only when nothing lies
 * between the point and the light. docs/05-shadows.md. */
#include "shade.h"

#include "app/trace.h"

bool shade_visible(const Scene *scene, const Hit *hit, vec3s l, float dist, RenderCtx *ctx)
{
  ctx->rays++; /* a shadow ray */
  /* BEGIN SOLUTION step 05 */
  /* The lecture traces a closest-hit ray and checks that it reaches the light.
   * Any occluder closer than the light will do, so ask the cheaper any-hit
   * query, stopping just short of the light. The origin is pushed off the
   * surface by its error bound, not by a fixed epsilon (docs/05-shadows.md). */
  return !scene_occluded(scene, ray_spawn(hit, l), ray_shadow_tmax(dist));
  /* STUB: return true; */
  /* END SOLUTION */
}

vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit,
                     vec3s *l, RenderCtx *ctx)
{
  float dist;
  vec3s li = light_incident(light, hit->p, hit->p_err, l, &dist);
  /* A light behind the surface adds nothing (shade_phong_light skips it): it
   * needs no shadow ray. */
  if (glms_vec3_dot(hit->n, *l) > 0.0f && !shade_visible(scene, hit, *l, dist, ctx))
    li = glms_vec3_zero();
  return trace_incident(ctx, (int)(light - scene->lights), li, *l, shade_phong_light);
}

/* inline: a hint that keeps it inlined into the render's loop, though the
 * tracer calls it too (trace_incident; docs/tracing.md). */
inline vec3s shade_phong_light(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l)
{
  trace_term(m, hit, v, li, l); /* --trace, --aov: its arguments */
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
static vec3s shade_light(const Scene *scene, int k, const Hit *hit, vec3s v, RenderCtx *ctx)
{
  vec3s l;
  vec3s li = shade_incident(scene, &scene->lights[k], hit, &l, ctx);
  return shade_phong_light(&scene->materials[hit->inst->material], hit, v, li, l);
}

vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye, RenderCtx *ctx)
{
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 04 */
  vec3s v = glms_vec3_normalize(glms_vec3_sub(eye, hit->p));
  for (int k = 0; k < scene->n_lights; k++)
    c = glms_vec3_add(c, shade_light(scene, k, hit, v, ctx));
  /* END SOLUTION */
  return c;
}

vec3s shade_trace(const Scene *scene, Ray ray, RenderCtx *ctx)
{
  Hit hit;
  ctx->rays++;
  if (!scene_intersect(scene, ray, INFINITY, &hit))
    return scene->background;
  trace_hit(ctx, &hit);
  return shade_phong(scene, &hit, ray.o, ctx);
}
