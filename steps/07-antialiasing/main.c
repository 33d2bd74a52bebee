/* Step 07, antialiasing: many camera samples per pixel, averaged (a box
 * filter), placed by a selectable sampler, and adaptive sampling that spends
 * them only where the first ones disagree. docs/07-antialiasing.md. */
#include "app/app.h"
#include "sampler.h"
#include "shade.h"

/* BEGIN SOLUTION step 07 */
/* Adaptive sampling looks first at a quarter of the budget, at least 4
 * samples: fewer miss slivers of thin objects (docs/07-antialiasing.md). */
enum { ADAPTIVE_MIN_FIRST = 4 };

/* Trace samples [first, first + count) of the pattern and add them to `acc`;
 * `lo` and `hi` keep each channel's smallest and largest displayed value. */
static void trace_samples(const Scene *scene, int i, int j, RenderCtx *ctx, int first,
                          int count, FilmAccum *acc, vec3s *lo, vec3s *hi)
{
  const RenderSettings *set = ctx->set;
  for (int k = first; k < first + count; k++) {
    ctx->sample = (uint32_t)k;
    ctx->samples++;
    vec2s s = sampler_get((SamplerKind)set->sampler, set->seed, ctx->pixel,
                          (uint32_t)k, (uint32_t)first, (uint32_t)count);
    /* Normalized film coordinates of the point s inside pixel (i, j). */
    float nx = ((float)i + s.x) / (float)scene->width;
    float ny = ((float)j + s.y) / (float)scene->height;
    vec3s c = shade_trace(scene, camera_ray(&scene->camera, nx, ny), ctx);
    film_accum_add(acc, c);
    vec3s shown = glms_vec3_clamp(c, 0.0f, 1.0f);
    *lo = glms_vec3_minv(*lo, shown);
    *hi = glms_vec3_maxv(*hi, shown);
  }
}
/* END SOLUTION */

/* The box filter: the pixel is the mean of its samples. With --adaptive T,
 * the first quarter of the budget (at least 4 samples) decides: when no
 * channel's shown values spread more than T, they are the answer; otherwise
 * the rest of the budget (the scene's samples) is spent as a second pattern
 * over the whole pixel. */
static vec3s pixel(const Scene *scene, const Film *film, int i, int j, RenderCtx *ctx)
{
  /* BEGIN SOLUTION step 07 */
  (void)film;
  int n = scene->samples;
  float threshold = ctx->set->adaptive;
  int first = n / 4 > ADAPTIVE_MIN_FIRST ? n / 4 : ADAPTIVE_MIN_FIRST;
  if (!(threshold > 0.0f) || first >= n)
    first = n;
  FilmAccum acc = {0};
  vec3s lo = glms_vec3_broadcast(1.0f), hi = glms_vec3_zero();
  trace_samples(scene, i, j, ctx, 0, first, &acc, &lo, &hi);
  if (first < n && vec_max_abs(glms_vec3_sub(hi, lo)) > threshold)
    trace_samples(scene, i, j, ctx, first, n - first, &acc, &lo, &hi);
  return film_accum_mean(&acc);
  /* STUB: vec2s s = film_sample(film, i, j); return shade_trace(scene, camera_ray(&scene->camera, s.x, s.y), ctx); */
  /* END SOLUTION */
}

int main(int argc, char **argv)
{
  const Step step = {
      .name = "07-antialiasing",
      .summary = "Step 07: antialiasing, several samples per pixel and adaptive sampling.\n"
                 "Defaults: the scene's samples, --sampler sobol, --adaptive 0.05.",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES |
                  SCENE_SAMPLES,
      .sampler = "sobol",
      .adaptive = 0.05f,
      .pixel = pixel,
  };
  return app_run(argc, argv, &step);
}
