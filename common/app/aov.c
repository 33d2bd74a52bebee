/* --aov NAME (common/app/aov.h): the step's pixel function renders every
 * pixel as usual, with a recorder per thread (common/app/trace_record.c) that
 * sums the quantity over the pixel's camera samples. README.md, "For
 * students". */
#include "app/aov.h"

#include <stdlib.h>
#include <string.h>

#include "app/trace_index.h"

static const char *const NAMES[] = {
    [AOV_NORMAL] = "normal",     [AOV_DEPTH] = "depth",       [AOV_ALBEDO] = "albedo",
    [AOV_AMBIENT] = "ambient",   [AOV_DIFFUSE] = "diffuse",   [AOV_SPECULAR] = "specular",
    [AOV_SHADOW] = "shadow",     [AOV_SAMPLES] = "samples"};
_Static_assert(sizeof NAMES / sizeof *NAMES == AOV_COUNT, "NAMES: one name per AovKind");
/* The Phong terms' AOVs are in TraceTerm's order (aov_term). */
_Static_assert(AOV_AMBIENT + TERM_DIFFUSE == AOV_DIFFUSE &&
                   AOV_AMBIENT + TERM_SPECULAR == AOV_SPECULAR &&
                   AOV_SPECULAR - AOV_AMBIENT + 1 == TERM_COUNT,
               "AovKind: ambient, diffuse, specular in TraceTerm's order");

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

/* The pixel as usual, through the recorder (its table answering with the
 * thread's counting scene); its value is the quantity. */
static vec3s aov_pixel(RenderWatch *w, const Scene *scene, const Film *film,
                       RenderPixelFn pixel, int i, int j)
{
  Trace *t = (Trace *)w; /* the watch is its first member */
  t->index.inner = scene;
  trace_begin_pixel(t);
  pixel(&t->scene, film, i, j);
  switch ((AovKind)t->aov) {
  case AOV_SHADOW:
    return glms_vec3_broadcast(t->shadow_rays ? (float)t->shadow_clear / (float)t->shadow_rays
                                              : 1.0f);
  case AOV_SAMPLES: return glms_vec3_broadcast((float)t->camera_rays);
  case AOV_NORMAL: return film_accum_mean(&t->normal);
  case AOV_DEPTH: return film_accum_mean(&t->depth);
  case AOV_ALBEDO: return film_accum_mean(&t->albedo);
  default: return glms_vec3_zero(); /* the Phong terms: rendered without a recorder */
  }
}

/* One recorder per thread, for `aov`; NULL (one line printed) when out of
 * memory. */
static Trace **recorders(const Scene *scene, AovKind aov, int threads)
{
  Trace **traces = calloc((size_t)threads, sizeof *traces);
  bool ok = traces != NULL;
  for (int k = 0; ok && k < threads; k++) {
    traces[k] = trace_new();
    ok = traces[k] && trace_init(traces[k], scene, TRACE_AOV);
    if (ok) {
      traces[k]->aov = (int)aov;
      traces[k]->watch.pixel = aov_pixel;
    }
  }
  if (ok)
    return traces;
  fprintf(stderr, "aov: out of memory\n");
  for (int k = 0; traces && k < threads; k++) {
    if (traces[k])
      trace_free(traces[k]);
    free(traces[k]);
  }
  free(traces);
  return NULL;
}

/* The Phong terms: the whole picture rendered on materials that keep one
 * term (the recorder's masked scene), the background black. */
bool aov_render(const Scene *scene, RenderPixelFn pixel, const RenderSettings *set,
                AovKind aov, Film *film, RenderStats *stats)
{
  int threads = render_threads(set);
  Trace **traces = recorders(scene, aov, threads);
  RenderWatch **watch = traces ? calloc((size_t)threads, sizeof *watch) : NULL;
  bool ok = watch != NULL;
  if (ok && aov_term(aov) >= 0) { /* unrecorded */
    render(&traces[0]->masked[aov_term(aov)], film, pixel, set, stats);
  } else if (ok) {
    for (int k = 0; k < threads; k++)
      watch[k] = &traces[k]->watch;
    RenderSettings with = *set;
    with.watch = watch;
    render(scene, film, pixel, &with, stats);
  } else if (traces) {
    fprintf(stderr, "aov: out of memory\n");
  }
  for (int k = 0; traces && k < threads; k++) {
    trace_free(traces[k]);
    free(traces[k]);
  }
  free(traces);
  free(watch);
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
