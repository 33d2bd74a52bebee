/* Step 07, antialiasing: the pixel as the mean colour over its square (a box
 * filter), from samples of a selectable pattern or, adaptively, from its
 * corners, cut in four where they differ. docs/07-antialiasing.md. */
#include "app/app.h"
#include "sampler.h"
#include "shade.h"

/* BEGIN SOLUTION step 07 */
/* Camera sample: the colour seen through the film point (x, y), in pixels
 * from the film's bottom-left corner. */
static vec3s point_colour(const Scene *scene, float x, float y, RenderCtx *ctx)
{
  ctx->samples++;
  float nx = x / (float)scene->width, ny = y / (float)scene->height;
  return shade_trace(scene, camera_ray(&scene->camera, nx, ny), ctx);
}

/* --adaptive 0: the mean of the N samples of the sampler's pattern inside
 * pixel (i, j), each keyed by its index (step 08's light samples use it). */
static vec3s pixel_sampled(const Scene *scene, int i, int j, RenderCtx *ctx)
{
  uint32_t n = (uint32_t)scene->samples;
  SamplerPattern pattern =
      sampler_pattern(ctx->set->sampler, ctx->set->seed, ctx->pixel, n);
  FilmAccum acc = {0};
  for (uint32_t k = 0; k < n; k++) {
    ctx->sample = k;
    vec2s s = sampler_point(&pattern, k);
    film_accum_add(&acc, point_colour(scene, (float)i + s.x, (float)j + s.y, ctx));
  }
  return film_accum_mean(&acc);
}

/* True when the shown colours (clamped to [0, 1], what the PNG keeps) of
 * c[0] .. c[n-1] spread more than the threshold in some channel. */
static bool colours_differ(const vec3s *c, int n, float threshold)
{
  vec3s lo = glms_vec3_broadcast(1.0f), hi = glms_vec3_zero();
  for (int k = 0; k < n; k++) {
    vec3s shown = glms_vec3_clamp(c[k], 0.0f, 1.0f);
    lo = glms_vec3_minv(lo, shown);
    hi = glms_vec3_maxv(hi, shown);
  }
  return vec_max_abs(glms_vec3_sub(hi, lo)) > threshold;
}

/* The colour at lattice point (x, y): render_point computes it with
 * point_colour the first time the tile asks, and remembers it. */
static vec3s at(const Scene *scene, RenderCtx *ctx, uint32_t x, uint32_t y)
{
  return render_point(scene, ctx, point_colour, x, y);
}

/* The mean colour over the square of side `size` (lattice units) whose
 * bottom-left corner is the lattice point (x, y); c holds the colours at its
 * corners: bottom left, bottom right, top left, top right. With the centre's
 * colour, when the five agree (or the square is a leaf, side <= `leaf`), the
 * answer is the mean of the corners' mean and the centre; otherwise the
 * square is cut in four and the answer is the mean of the quarters'. */
static vec3s square_mean(const Scene *scene, RenderCtx *ctx, uint32_t x, uint32_t y,
                         uint32_t size, uint32_t leaf, const vec3s c[4])
{
  uint32_t h = size / 2;
  const vec3s f[5] = {c[0], c[1], c[2], c[3], at(scene, ctx, x + h, y + h)};
  if (size <= leaf || !colours_differ(f, 5, ctx->set->adaptive)) {
    vec3s corners = glms_vec3_add(glms_vec3_add(c[0], c[1]), glms_vec3_add(c[2], c[3]));
    return glms_vec3_add(glms_vec3_scale(corners, 0.125f), glms_vec3_scale(f[4], 0.5f));
  }
  /* The midpoints of the bottom, left, right and top sides. */
  vec3s m = f[4], b = at(scene, ctx, x + h, y), l = at(scene, ctx, x, y + h);
  vec3s r = at(scene, ctx, x + size, y + h), t = at(scene, ctx, x + h, y + size);
  const vec3s q[4][4] = {{c[0], b, l, m}, {b, c[1], m, r}, {l, m, c[2], t}, {m, r, t, c[3]}};
  vec3s sum = glms_vec3_zero();
  for (uint32_t k = 0; k < 4; k++)
    sum = glms_vec3_add(sum, square_mean(scene, ctx, x + (k & 1) * h, y + (k >> 1) * h, h,
                                         leaf, q[k]));
  return glms_vec3_scale(sum, 0.25f);
}
/* END SOLUTION */

/* The box filter: the pixel is the mean colour over its square. With
 * --adaptive T > 0, from its corners (each shared with the neighbours) and
 * centre, the square cut in four wherever they differ by more than T, down to
 * squares of side 2/sqrt(samples) (so the closest samples are 1/sqrt(samples)
 * apart, as in a sqrt(samples) x sqrt(samples) grid); with --adaptive 0, the
 * mean of `samples` samples of the chosen pattern. */
static vec3s pixel(const Scene *scene, const Film *film, int i, int j, RenderCtx *ctx)
{
  /* BEGIN SOLUTION step 07 */
  (void)film;
  if (!(ctx->set->adaptive > 0.0f))
    return pixel_sampled(scene, i, j, ctx);
  uint32_t leaf = RENDER_LATTICE; /* halved for each factor 4 of samples past 4 */
  for (int n = scene->samples; n >= 16 && leaf > 2; n /= 4)
    leaf /= 2;
  uint32_t x = (uint32_t)i * RENDER_LATTICE, y = (uint32_t)j * RENDER_LATTICE, s = RENDER_LATTICE;
  const vec3s c[4] = {at(scene, ctx, x, y), at(scene, ctx, x + s, y),
                      at(scene, ctx, x, y + s), at(scene, ctx, x + s, y + s)};
  return square_mean(scene, ctx, x, y, s, leaf, c);
  /* STUB: vec2s s = film_sample(film, i, j); return shade_trace(scene, camera_ray(&scene->camera, s.x, s.y), ctx); */
  /* END SOLUTION */
}

int main(int argc, char **argv)
{
  const Step step = {
      STEP_MANIFEST, /* name, summary, features, sampler, adaptive: step.mk */
      .pixel = pixel,
  };
  return app_run(argc, argv, &step);
}
