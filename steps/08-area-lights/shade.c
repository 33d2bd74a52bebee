/* Step 08: area lights. A parallelogram light is sampled as N small point
 * lights spread over it in strata, and shadow rays are saved where the first
 * samples agree the light is all visible or all hidden. docs/08-area-lights.md. */
#include "shade.h"

#include "rng.h"
#include "sampler.h"

vec3s shade_incident(const Scene *scene, const Light *light, const Hit *hit,
                     vec3s *l, RenderCtx *ctx)
{
  float dist;
  vec3s li = light_incident(light, hit->p, hit->p_err, l, &dist);
  /* BEGIN SOLUTION step 05 */
  /* A light behind the surface adds nothing (shade_phong skips it): no
   * shadow ray for it. */
  if (!(glms_vec3_dot(hit->n, *l) > 0.0f))
    return li;
  /* The lecture traces a closest-hit ray and checks that it reaches the light.
   * Any occluder closer than the light will do, so ask the cheaper any-hit
   * query, stopping just short of the light (docs/05-shadows.md). The origin
   * is pushed off the surface by its error bound, not by a fixed epsilon. */
  Ray shadow = ray_spawn(hit, *l);
  ctx->rays++;
  if (scene_occluded(scene, shadow, dist * (1.0f - 0x1p-20f)))
    return glms_vec3_zero();
  /* END SOLUTION */
  return li;
}

/* Phong's term for one light: radiance li arriving from unit direction l. */
static vec3s phong_light(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l)
{
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 04 */
  float n_dot_l = glms_vec3_dot(hit->n, l);
  if (!(n_dot_l > 0.0f)) /* light behind the surface: no diffuse, no specular */
    return c;
  c = glms_vec3_scale(glms_vec3_mul(m->diffuse, li), n_dot_l);
  if (!vec_is_zero(m->specular)) {
    /* The lecture's slide omits L_i here; without it the highlight would not
     * dim with distance or light power (docs/04-phong.md). */
    vec3s r = vec_reflect(glms_vec3_negate(l), hit->n);
    float lobe = powf(fmaxf(0.0f, glms_vec3_dot(r, v)), m->shininess);
    c = glms_vec3_add(c, glms_vec3_scale(glms_vec3_mul(m->specular, li), lobe));
  }
  /* END SOLUTION */
  return c;
}

/* BEGIN SOLUTION step 08 */
/* How one shading point spreads its N samples over the light: step 07's
 * patterns (sampler_get) on the light's parameters (a, b) in [0,1)^2. */
typedef struct LightPattern {
  SamplerKind kind;
  uint32_t key;   /* the seed sampler_get is given */
  uint32_t pixel;
  int n;          /* samples of this light */
} LightPattern;

static LightPattern pattern_make(const RenderCtx *ctx, int light, int n)
{
  /* A key of its own for each light and camera sample: the first draw of the
   * stream (seed ^ golden * (light + 1), pixel, camera sample). Keyed by the
   * seed alone, every camera sample of a pixel would reuse one light pattern
   * and the light would get N samples per pixel instead of N per sample. */
  Rng r = rng_make(ctx->set->seed ^ (0x9e3779b9u * (uint32_t)(light + 1)), ctx->pixel,
                   ctx->sample);
  LightPattern pat = {.kind = (SamplerKind)ctx->set->sampler, .key = rng_next(&r),
                      .pixel = ctx->pixel, .n = n};
  return pat;
}

/* One of N samples as a point light of power (P/N) cos(theta_light): its
 * radiance at the hit point, *l toward it and *dist to it. Zero when the point
 * is behind the light (one-sided) or on it. */
static vec3s area_incident(const Light *light, const LightPattern *pat, int k,
                           const Hit *hit, vec3s *l, float *dist)
{
  vec2s ab = sampler_get(pat->kind, pat->key, pat->pixel, (uint32_t)k, 0, (uint32_t)pat->n);
  vec3s to_x = glms_vec3_sub(quad_point(&light->quad, ab.x, ab.y), hit->p);
  float r2 = glms_vec3_dot(to_x, to_x);
  *dist = sqrtf(r2);
  if (!(*dist > hit->p_err))
    return glms_vec3_zero();
  *l = glms_vec3_scale(to_x, 1.0f / *dist);
  float cos_light = -glms_vec3_dot(*l, light->quad.normal);
  if (!(cos_light > 0.0f))
    return glms_vec3_zero();
  return glms_vec3_scale(light->power, cos_light / ((float)pat->n * r2));
}

/* The shadow test of a sample at distance dist in unit direction l (any-hit
 * query stopping just short of the light, as in step 05). */
static bool sample_lit(const Scene *scene, const Hit *hit, vec3s l, float dist,
                       RenderCtx *ctx)
{
  ctx->rays++;
  return !scene_occluded(scene, ray_spawn(hit, l), dist * (1.0f - 0x1p-20f));
}

/* Adaptive sampling: shadow rays to the light's four corners first. All
 * lit: the samples are taken as lit, with no shadow ray of their own; all
 * dark (or facing away): the light adds nothing. Returns 1 (all lit), 0 (all
 * dark) or -1 (mixed: every sample needs its shadow ray). The corners are the
 * points of the light farthest apart, the likeliest to see an occluder's edge. */
static int probe_corners(const Scene *scene, const Light *light, const Hit *hit,
                         RenderCtx *ctx)
{
  int lit = 0;
  for (int j = 0; j < 4; j++) {
    vec3s to_x = glms_vec3_sub(quad_point(&light->quad, (float)(j & 1), (float)(j >> 1)),
                               hit->p);
    float dist = glms_vec3_norm(to_x);
    vec3s l = glms_vec3_scale(to_x, 1.0f / dist);
    if (glms_vec3_dot(hit->n, l) > 0.0f && glms_vec3_dot(l, light->quad.normal) < 0.0f)
      lit += sample_lit(scene, hit, l, dist, ctx);
  }
  return lit == 4 ? 1 : lit == 0 ? 0 : -1;
}
/* END SOLUTION */

vec3s shade_area(const Scene *scene, int light_index, const Hit *hit, vec3s eye,
                 RenderCtx *ctx)
{
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 08 */
  const Light *light = &scene->lights[light_index];
  const Material *m = &scene->materials[hit->inst->material];
  vec3s v = glms_vec3_normalize(glms_vec3_sub(eye, hit->p));
  int n = ctx->set->light_samples > 0 ? ctx->set->light_samples : 1;
  LightPattern pat = pattern_make(ctx, light_index, n);
  /* Adaptive: the four corner rays decide. Otherwise, when no shape can meet
   * the shadow volume (the hull of p and the light), every sample is visible
   * and needs no shadow ray. Either pays only with more than four samples. */
  int agreed = n <= 4                        ? -1
               : ctx->set->adaptive > 0.0f   ? probe_corners(scene, light, hit, ctx)
               : scene_quad_unoccluded(scene, hit, &light->quad) ? 1
                                                                 : -1;
  if (agreed == 0)
    return c;
  for (int k = 0; k < n; k++) {
    vec3s l;
    float dist;
    vec3s li = area_incident(light, &pat, k, hit, &l, &dist);
    if (vec_is_zero(li) || !(glms_vec3_dot(hit->n, l) > 0.0f))
      continue;
    if (agreed < 0 && !sample_lit(scene, hit, l, dist, ctx))
      continue;
    c = glms_vec3_add(c, phong_light(m, hit, v, li, l));
  }
  /* END SOLUTION */
  return c;
}

vec3s shade_phong(const Scene *scene, const Hit *hit, vec3s eye, RenderCtx *ctx)
{
  const Material *m = &scene->materials[hit->inst->material];
  vec3s c = glms_vec3_zero();
  /* BEGIN SOLUTION step 06 */
  /* m_amb * l_amb: skipped when the scene has no ambient light at all. */
  if (scene->info.ambient)
    c = glms_vec3_mul(m->ambient, scene->ambient);
  /* END SOLUTION */
  /* BEGIN SOLUTION step 04 */
  vec3s v = glms_vec3_normalize(glms_vec3_sub(eye, hit->p));
  for (int k = 0; k < scene->n_lights; k++) {
    if (scene->lights[k].type == LIGHT_AREA) { /* N point lights (step 08) */
      c = glms_vec3_add(c, shade_area(scene, k, hit, eye, ctx));
      continue;
    }
    vec3s l;
    vec3s li = shade_incident(scene, &scene->lights[k], hit, &l, ctx);
    c = glms_vec3_add(c, phong_light(m, hit, v, li, l));
  }
  /* END SOLUTION */
  return c;
}

vec3s shade_trace(const Scene *scene, Ray ray, RenderCtx *ctx)
{
  Hit hit;
  ctx->rays++;
  if (!scene_intersect(scene, ray, INFINITY, &hit))
    return scene->background;
  /* BEGIN SOLUTION step 08 */
  if (hit.inst->light >= 0 && scene->lights[hit.inst->light].type == LIGHT_AREA) {
    /* The front face shows the radiance L = P / A; the light is one-sided and
     * its back emits nothing: black (docs/08-area-lights.md). */
    const Light *area = &scene->lights[hit.inst->light];
    return hit.backface ? glms_vec3_zero() : glms_vec3_divs(area->power, area->quad.area);
  }
  /* END SOLUTION */
  /* BEGIN SOLUTION step 06 */
  if (hit.inst->light >= 0) {
    /* A point light's sphere shows the radiance P / t^2 it sends this far. */
    const Light *light = &scene->lights[hit.inst->light];
    return glms_vec3_divs(light->power, hit.t * hit.t);
  }
  /* STUB: if (hit.inst->light >= 0) return glms_vec3_zero(); */
  /* END SOLUTION */
  return shade_phong(scene, &hit, ray.o, ctx);
}
