/* --aov NAME (common/app/aov.h): the step's pixel function renders every
 * pixel as usual, with a recorder per thread (common/app/trace.c) that sums
 * the quantity over the pixel's camera samples. README.md, "For students". */
#include "app/aov.h"

#include <stdlib.h>
#include <string.h>

#include "app/trace_state.h"

static const char *const NAMES[AOV_COUNT] = {"normal", "depth", "albedo", "ambient",
                                             "diffuse", "specular", "shadow", "samples"};

bool aov_parse(const char *name, AovKind *out)
{
  for (int k = 0; k < AOV_COUNT; k++)
    if (!strcmp(name, NAMES[k])) {
      *out = (AovKind)k;
      return true;
    }
  return false;
}

const char *aov_name(AovKind aov)
{
  return NAMES[aov];
}

int aov_term(int aov)
{
  return aov >= AOV_AMBIENT && aov <= AOV_SPECULAR ? aov - AOV_AMBIENT : -1;
}

void aov_camera_hit(Trace *t, const Scene *scene, const Hit *hit)
{
  vec3s v = glms_vec3_zero();
  if (t->aov == AOV_DEPTH) {
    if (hit) {
      film_accum_add(&t->sum, glms_vec3_broadcast(hit->t));
      t->hits++;
    }
    return;
  }
  if (t->aov == AOV_NORMAL && hit)
    v = glms_vec3_scale(glms_vec3_adds(hit->n, 1.0f), 0.5f);
  else if (t->aov == AOV_ALBEDO && hit && hit->inst->material >= 0)
    v = scene->materials[hit->inst->material].diffuse;
  else if (t->aov != AOV_NORMAL && t->aov != AOV_ALBEDO)
    return;
  film_accum_add(&t->sum, v);
}

void aov_shadow_ray(Trace *t, bool blocked)
{
  t->shadow_rays++;
  t->shadow_clear += !blocked;
}

/* The pixel as usual, through the recorder; its value is the quantity. */
static vec3s aov_pixel(const Scene *scene, const Film *film, int i, int j, RenderCtx *ctx)
{
  (void)scene;
  Trace *t = ctx->trace;
  trace_begin_pixel(t);
  t->pixel(&t->scene, film, i, j, ctx);
  switch ((AovKind)t->aov) {
  case AOV_SHADOW:
    return glms_vec3_broadcast(t->shadow_rays ? (float)t->shadow_clear / (float)t->shadow_rays
                                              : 1.0f);
  case AOV_SAMPLES: return glms_vec3_broadcast((float)t->camera_rays);
  default: return t->sum.n ? film_accum_mean(&t->sum) : glms_vec3_zero();
  }
}

bool aov_render(const Scene *scene, RenderPixelFn pixel, const RenderSettings *set,
                AovKind aov, Film *film, RenderStats *stats)
{
  int threads = render_threads(set);
  Trace **traces = calloc((size_t)threads, sizeof *traces);
  bool ok = traces != NULL;
  for (int k = 0; ok && k < threads; k++) {
    traces[k] = trace_new();
    ok = traces[k] && trace_init(traces[k], scene, false, (int)aov);
    if (ok)
      traces[k]->pixel = pixel;
  }
  if (ok) {
    RenderSettings with = *set;
    with.traces = traces;
    render(scene, film, aov_pixel, &with, stats);
  } else {
    fprintf(stderr, "aov: out of memory\n");
  }
  for (int k = 0; traces && k < threads; k++) {
    if (traces[k])
      trace_free(traces[k]);
    free(traces[k]);
  }
  free(traces);
  return ok;
}

bool aov_file_is_bytes(const char *path)
{
  const char *dot = strrchr(path, '.');
  return !dot || (strcmp(dot, ".pfm") && strcmp(dot, ".hdr"));
}

void aov_for_bytes(AovKind aov, int budget, Film *film)
{
  size_t n = (size_t)film->width * film->height * 3;
  float near = INFINITY;
  for (size_t k = 0; aov == AOV_DEPTH && k < n; k++)
    if (film->rgb[k] > 0.0f && film->rgb[k] < near)
      near = film->rgb[k];
  for (size_t k = 0; k < n; k++) {
    if (aov == AOV_DEPTH && film->rgb[k] > 0.0f)
      film->rgb[k] = near / film->rgb[k];
    else if (aov == AOV_SAMPLES)
      film->rgb[k] /= (float)(budget > 0 ? budget : 1);
  }
}
