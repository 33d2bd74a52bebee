/* The recording index of --trace and --aov (common/app/trace_index.h): a
 * copy of the scene whose SceneIndex records each query (camera rays, shadow
 * rays, their answers) and answers it with the scene's own index, and the
 * copies of the scene whose materials keep one term. README.md, "For
 * students"; docs/tracing.md. */
#include "app/trace_index.h"

#include <stdlib.h>
#include <string.h>

/* "#2 sphere red", "#5 sphere light 0": what an instance is. */
static void label(const Scene *scene, const Instance *inst, char *buf, size_t size)
{
  int id = (int)(inst - scene->instances);
  if (inst->material >= 0)
    snprintf(buf, size, "#%d %s %s", id, scene_shape_name(inst->shape),
             scene->materials[inst->material].name);
  else
    snprintf(buf, size, "#%d %s light %d", id, scene_shape_name(inst->shape), inst->light);
}

/* The nearest of the first `count` instances on the ray before *tmax (*tmax
 * becoming its distance), each tested with the shape's own function; NULL
 * when none. What scene.c's loop answers, without an index. */
static const Instance *nearest(const Scene *scene, int count, Ray r, float *tmax)
{
  const Instance *best = NULL;
  for (int k = 0; k < count; k++) {
    float t = scene_instance_hit_t(&scene->instances[k], r, *tmax);
    if (t < *tmax) {
      *tmax = t;
      best = &scene->instances[k];
    }
  }
  return best;
}

/* ---------------------------------------------------------------- queries */

static void shadow_query(Trace *t, Ray r, float tmax, bool blocked)
{
  if (t->mode == TRACE_AOV) {
    t->shadow_rays++;
    t->shadow_clear += !blocked;
    return;
  }
  TraceLine *line = trace_add(&t->rays, 0, t->compact ? "light sample" : "shadow ray",
                              TRACE_DOC_SHADOW);
  if (!t->compact)
    trace_vec(line, "o", r.o);
  trace_vec(line, "d", r.d);
  trace_num(line, "tmax", tmax);
  float at = tmax;
  const Instance *in_way = blocked ? nearest(&t->plain, t->plain.n_shapes, r, &at) : NULL;
  char what[TRACE_WORD] = "none";
  if (in_way)
    label(&t->plain, in_way, what, sizeof what);
  trace_word(line, "occluder", blocked && !in_way ? "yes" : what);
  if (in_way && !t->compact)
    trace_num(line, "at", at);
  t->rays_blocked += blocked;
}

static void camera_query(Trace *t, Ray r, const Instance *hit, float t_hit)
{
  const Scene *scene = &t->plain;
  char what[TRACE_WORD] = "none";
  if (hit)
    label(scene, hit, what, sizeof what);
  if (t->compact) {
    char key[24];
    snprintf(key, sizeof key, "sample %d", t->camera_rays - 1);
    TraceLine *line = trace_add(&t->lines, 0, key, TRACE_DOC_SAMPLE);
    trace_vec(line, "d", r.d);
    trace_word(line, "hit", what);
    trace_num(line, "t", t_hit);
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
  if (!hit)
    trace_vec(line, "background", scene->background);
}

/* A closest-hit query is a camera ray when it starts the pixel or starts at
 * the eye, and is not asked while a light is shaded again; otherwise it is a
 * shadow test (the lecture's closest-hit version). A shadow ray of the
 * pixel's own run is --aov's; --trace records those of each light shaded
 * again (app/trace_record.c). */
static const Instance *traced_closest(const Scene *scene, const Ray *ray, float *tmax)
{
  Ray r = *ray;
  Trace *t = ((const TraceIndex *)scene->index)->trace;
  float limit = *tmax;
  const Instance *hit = scene_closest(t->index.inner, ray, tmax);
  vec3s eye = t->plain.camera.eye;
  bool camera = !t->replaying && (t->camera_next || (r.o.x == eye.x && r.o.y == eye.y &&
                                                     r.o.z == eye.z));
  if (!camera) { /* blocked by a lit shape: lights' shapes never block */
    if (t->replaying || t->mode == TRACE_AOV)
      shadow_query(t, r, limit, hit && hit->material >= 0);
    return hit;
  }
  trace_end_sample(t);
  t->camera_next = false;
  t->camera_rays++;
  t->eye = r.o;
  if (t->mode == TRACE_RECORD) {
    trace_flush_rays(t, 1);
    camera_query(t, r, hit, hit ? *tmax : INFINITY);
  }
  Hit h;
  trace_on_hit(t, hit && scene_intersect(&t->plain, r, limit, &h) ? &h : NULL);
  return hit;
}

static bool traced_any(const Scene *scene, const Ray *ray, float tmax)
{
  Trace *t = ((const TraceIndex *)scene->index)->trace;
  bool blocked = scene_any(t->index.inner, ray, tmax);
  if (t->replaying || t->mode == TRACE_AOV)
    shadow_query(t, *ray, tmax, blocked);
  return blocked;
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

bool trace_init(Trace *t, const Scene *scene, TraceMode mode)
{
  memset(t, 0, sizeof *t);
  t->mode = mode;
  t->compact = scene->samples > 1;
  t->camera_doc = TRACE_DOC_CAMERA;
  t->plain = t->scene = *scene;
  t->index = (TraceIndex){.base = {.closest = traced_closest, .any = traced_any},
                          .inner = scene, .trace = t};
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
  for (int k = 0; k < TERM_COUNT; k++) {
    free(t->materials[k]);
  }
  trace_lines_free(&t->lines);
  trace_lines_free(&t->rays);
  memset(t, 0, sizeof *t);
}

