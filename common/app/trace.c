/* --trace X Y (README.md, "For students"): one pixel rendered alone by the
 * step's own pixel function, on a copy of the scene whose index records each
 * query (the camera ray and its closest hit, each shadow ray and its answer)
 * and answers it with the scene's own index. The steps' hooks (trace.h) add
 * each light's l, n.l and L_i, and the terms, which come from calling the
 * step's functions again, unrecorded, on materials that keep one term. */
#include "app/trace_state.h"

#include <stdlib.h>
#include <string.h>

#include "app/aov.h"

/* "#2 sphere red", "#5 sphere light 0": what an instance is. */
static void label(const Scene *scene, const Instance *inst, char *buf, size_t size)
{
  static const char *const shape[] = {"sphere", "plane", "quad"};
  int id = (int)(inst - scene->instances);
  if (inst->material >= 0)
    snprintf(buf, size, "#%d %s %s", id, shape[inst->shape],
             scene->materials[inst->material].name);
  else
    snprintf(buf, size, "#%d %s light %d", id, shape[inst->shape], inst->light);
}

/* ---------------------------------------------------------------- queries */

/* The nearest lit shape on the ray before tmax (what blocks a shadow ray),
 * each tested with the shape's own function; NULL when none. */
static const Instance *occluder(const Scene *scene, Ray r, float tmax, float *t_out)
{
  const Instance *best = NULL;
  for (int k = 0; k < scene->n_shapes; k++) {
    float t = scene_instance_hit_t(&scene->instances[k], r, tmax);
    if (t < tmax) {
      tmax = t;
      best = &scene->instances[k];
    }
  }
  *t_out = tmax;
  return best;
}

static void shadow_query(Trace *t, const Scene *scene, Ray r, float tmax, bool blocked)
{
  if (!t->record) {
    aov_shadow_ray(t, blocked);
    return;
  }
  TraceLine *line = trace_add(&t->rays, 0, t->compact ? "light sample" : "shadow ray",
                              TRACE_DOC_SHADOW);
  if (!t->compact)
    trace_vec(line, "o", r.o);
  trace_vec(line, "d", r.d);
  trace_num(line, "tmax", tmax);
  float at;
  const Instance *in_way = blocked ? occluder(scene, r, tmax, &at) : NULL;
  char what[TRACE_WORD] = "none";
  if (in_way)
    label(scene, in_way, what, sizeof what);
  trace_word(line, "occluder", blocked && !in_way ? "yes" : what);
  t->rays_blocked += blocked;
  if (in_way && !t->compact)
    trace_num(line, "at", at);
}

static void camera_query(Trace *t, const Scene *scene, Ray r, const Hit *hit)
{
  char what[TRACE_WORD] = "none";
  if (hit)
    label(scene, hit->inst, what, sizeof what);
  if (t->compact) {
    char key[24];
    snprintf(key, sizeof key, "sample %u", t->sample);
    TraceLine *line = trace_add(&t->lines, 0, key, TRACE_DOC_SAMPLE);
    trace_vec(line, "d", r.d);
    trace_word(line, "hit", what);
    trace_num(line, "t", hit ? hit->t : INFINITY);
    trace_vec(line, "rgb", t->colour);
    return;
  }
  TraceLine *line = trace_add(&t->lines, 0, "camera ray", t->camera_doc);
  trace_vec(line, "o", r.o);
  trace_vec(line, "d", r.d);
  for (int k = 0; k < scene->n_instances; k++) {
    char id[TRACE_WORD];
    label(scene, &scene->instances[k], id, sizeof id);
    line = trace_add(&t->lines, 1, "instance", TRACE_DOC_HIT);
    trace_word(line, "id", id);
    float t_k = scene_instance_hit_t(&scene->instances[k], r, INFINITY);
    if (t_k < INFINITY)
      trace_num(line, "t", t_k);
    else
      trace_word(line, "t", "miss");
  }
  line = trace_add(&t->lines, 0, "closest hit", TRACE_DOC_HIT);
  trace_word(line, "hit", what);
  if (!hit) {
    trace_vec(line, "background", scene->background);
    return;
  }
  trace_num(line, "t", hit->t);
  trace_vec(line, "p", hit->p);
  trace_vec(line, "n", hit->n);
  trace_word(line, "backface", hit->backface ? "yes" : "no");
}

static const Instance *traced_closest(const Scene *scene, Ray r, float *tmax)
{
  const TraceIndex *ix = (const TraceIndex *)scene->index;
  Trace *t = ix->trace;
  Scene in = *scene;
  in.index = ix->inner;
  Hit hit;
  bool found = scene_intersect(&in, r, *tmax, &hit);
  if (!t->camera_next) { /* a closest-hit query while shading: a shadow test */
    shadow_query(t, &in, r, *tmax, found);
  } else {
    t->camera_next = false;
    t->camera_rays++;
    if (t->record)
      camera_query(t, &in, r, found ? &hit : NULL);
    else
      aov_camera_hit(t, &in, found ? &hit : NULL);
  }
  if (!found)
    return NULL;
  *tmax = hit.t;
  return hit.inst;
}

static bool traced_any(const Scene *scene, Ray r, float tmax)
{
  const TraceIndex *ix = (const TraceIndex *)scene->index;
  Scene in = *scene;
  in.index = ix->inner;
  bool blocked = scene_occluded(&in, r, tmax);
  shadow_query(ix->trace, &in, r, tmax, blocked);
  return blocked;
}

/* ---------------------------------------------------------------- hooks */

/* Show the shadow rays traced since the last light under it, at `depth`. */
static void flush_rays(Trace *t, int depth)
{
  for (int k = 0; k < t->rays.n; k++) {
    t->rays.line[k].depth = depth;
    trace_lines_push(&t->lines, &t->rays.line[k]);
  }
  t->rays.n = t->rays_blocked = 0;
}

void trace_end_sample(Trace *t)
{
  if (!t->record)
    return;
  flush_rays(t, 1);
  if (t->shaded && !t->compact)
    for (int k = 0; k < TERM_COUNT; k++)
      trace_vec(trace_add(&t->lines, 0, aov_name((AovKind)(AOV_AMBIENT + k)), k == TERM_AMBIENT ? TRACE_DOC_AMBIENT : TRACE_DOC_LIGHT),
                "rgb", t->term[k]);
  t->shaded = false;
}

void trace_ray_(RenderCtx *ctx, const Scene *scene, Ray ray, TraceShadeFn shade)
{
  (void)scene;
  Trace *t = ctx->trace;
  trace_end_sample(t);
  t->camera_next = true;
  t->sample = ctx->sample;
  int only = aov_term(t->aov);
  if (!t->record && only < 0)
    return;
  /* The sample's colour and terms: the step's shade_trace on the plain and
   * masked scenes, unrecorded. Lights' shapes and the background belong to
   * no term. */
  RenderCtx quiet = *ctx;
  quiet.trace = NULL;
  Hit hit;
  bool lit = scene_intersect(&t->plain, ray, INFINITY, &hit) && hit.inst->material >= 0;
  if (t->record)
    t->colour = shade(&t->plain, ray, &quiet);
  for (int k = 0; k < TERM_COUNT; k++) {
    if (!t->record && k != only)
      continue;
    t->term[k] = lit ? shade(&t->masked[k], ray, &quiet) : glms_vec3_zero();
    film_accum_add(t->record ? &t->term_sum[k] : &t->sum, t->term[k]);
  }
  t->shaded = true;
}

static const char *light_type(const Light *light)
{
  return light->type == LIGHT_POINT ? "point" : light->type == LIGHT_AREA ? "area" : "directional";
}

void trace_light_(RenderCtx *ctx, const Scene *scene, int k, const Hit *hit, vec3s v,
                  vec3s li, vec3s l, TraceLightFn phong_light)
{
  Trace *t = ctx->trace;
  if (!t->record)
    return;
  int m = hit->inst->material;
  vec3s dif = phong_light(&t->materials[TERM_DIFFUSE][m], hit, v, li, l);
  vec3s spe = phong_light(&t->materials[TERM_SPECULAR][m], hit, v, li, l);
  char key[24];
  snprintf(key, sizeof key, "light %d %s", k, light_type(&scene->lights[k]));
  int depth = t->compact;
  TraceLine *line = trace_add(&t->lines, depth, key, TRACE_DOC_LIGHT);
  trace_vec(line, "l", l);
  trace_num(line, "n.l", glms_vec3_dot(hit->n, l));
  trace_vec(line, "L_i", li);
  if (t->compact) {
    const TraceLine *ray = t->rays.n ? &t->rays.line[t->rays.n - 1] : NULL;
    trace_word(line, "occluder", ray ? ray->f[ray->n_fields - 1].word : "no ray");
    t->rays.n = t->rays_blocked = 0;
    trace_vec(line, "diffuse", dif);
    trace_vec(line, "specular", spe);
    return;
  }
  flush_rays(t, depth + 1);
  trace_vec(trace_add(&t->lines, depth + 1, "diffuse", TRACE_DOC_LIGHT), "rgb", dif);
  trace_vec(trace_add(&t->lines, depth + 1, "specular", TRACE_DOC_LIGHT), "rgb", spe);
}

void trace_area_(RenderCtx *ctx, const Scene *scene, int k, const Hit *hit, vec3s v,
                 TraceAreaFn area)
{
  Trace *t = ctx->trace;
  if (!t->record) { /* a point nothing can shadow traced no ray: all clear */
    for (int n = scene->no_occluders ? ctx->set->light_samples : 0; n > 0; n--)
      aov_shadow_ray(t, false);
    return;
  }
  RenderCtx quiet = *ctx;
  quiet.trace = NULL;
  vec3s dif = area(&t->masked[TERM_DIFFUSE], k, hit, v, &quiet);
  vec3s spe = area(&t->masked[TERM_SPECULAR], k, hit, v, &quiet);
  char key[24];
  snprintf(key, sizeof key, "light %d %s", k, light_type(&scene->lights[k]));
  int depth = t->compact;
  TraceLine *line = trace_add(&t->lines, depth, key, TRACE_DOC_AREA);
  trace_num(line, "samples", ctx->set->light_samples);
  if (scene->no_occluders) /* the renderer proved nothing can block the light */
    trace_word(line, "shadow rays", "none needed (shadow-volume test)");
  else
    trace_num(line, "shadow rays", t->rays.n);
  trace_num(line, "blocked", t->rays_blocked);
  trace_vec(line, "diffuse", dif);
  trace_vec(line, "specular", spe);
  flush_rays(t, depth + 1);
}

/* ---------------------------------------------------------------- set-up */

static Material mask(Material m, int term)
{
  if (term != TERM_AMBIENT)
    m.ambient = glms_vec3_zero();
  if (term != TERM_DIFFUSE)
    m.diffuse = glms_vec3_zero();
  if (term != TERM_SPECULAR)
    m.specular = glms_vec3_zero();
  return m;
}

Trace *trace_new(void)
{
  size_t align = _Alignof(Trace), size = (sizeof(Trace) + align - 1) / align * align;
  Trace *t = aligned_alloc(align, size);
  if (t)
    memset(t, 0, sizeof *t);
  return t;
}

bool trace_init(Trace *t, const Scene *scene, bool record, int aov)
{
  memset(t, 0, sizeof *t);
  t->record = record;
  t->aov = aov;
  t->compact = scene->samples > 1;
  t->camera_doc = TRACE_DOC_CAMERA;
  t->plain = t->scene = *scene;
  t->index = (TraceIndex){.base = {.closest = traced_closest, .any = traced_any},
                          .inner = scene->index, .trace = t};
  t->scene.index = &t->index.base;
  for (int k = 0; k < TERM_COUNT; k++) {
    size_t n = (size_t)scene->n_materials;
    t->materials[k] = malloc((n ? n : 1) * sizeof(Material));
    if (!t->materials[k]) {
      fprintf(stderr, "trace: out of memory\n");
      trace_free(t);
      return false;
    }
    for (size_t m = 0; m < n; m++)
      t->materials[k][m] = mask(scene->materials[m], k);
    t->masked[k] = *scene;
    t->masked[k].materials = t->materials[k];
    t->masked[k].background = glms_vec3_zero();
  }
  return true;
}

void trace_free(Trace *t)
{
  for (int k = 0; k < TERM_COUNT; k++)
    free(t->materials[k]);
  trace_lines_free(&t->lines);
  trace_lines_free(&t->rays);
  memset(t, 0, sizeof *t);
}

void trace_begin_pixel(Trace *t)
{
  t->camera_next = true;
  t->camera_rays = 0;
  t->shaded = false;
  t->sum = (FilmAccum){0};
  t->hits = t->shadow_rays = t->shadow_clear = 0;
  for (int k = 0; k < TERM_COUNT; k++)
    t->term_sum[k] = (FilmAccum){0};
}
