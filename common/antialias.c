/* Antialiasing (step 07; common/antialias.h): the pixel sampler of the
 * lecture's film, several samples per pixel. docs/07-antialiasing.md. */
#include "antialias.h"

#include "app/render_point.h"
#include "film.h"
#include "sampler.h"
#include "scene.h"
#include "shade.h"

/* BEGIN SOLUTION step 07 */
/* Camera sample: the colour seen through the film point (x, y), in pixels
 * from the film's bottom-left corner. */
static vec3s point_colour(const Scene *scene, float x, float y)
{
  float nx = x / (float)scene->width, ny = y / (float)scene->height;
  return shade_sample(scene, nx, ny);
}

/* Adaptive off: the mean of the N samples of the scene's pattern inside
 * pixel (i, j). */
static vec3s pixel_sampled(const Scene *scene, int i, int j)
{
  uint32_t n = (uint32_t)scene->samples;
  uint32_t pixel = (uint32_t)j * (uint32_t)scene->width + (uint32_t)i;
  SamplerPattern pattern =
      sampler_pattern(scene->sampler.kind, scene->sampler.seed, pixel, n);
  FilmAccum acc = {0};
  for (uint32_t k = 0; k < n; k++) {
    vec2s s = sampler_point(&pattern, k);
    film_accum_add(&acc, point_colour(scene, (float)i + s.x, (float)j + s.y));
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
static vec3s at(const Scene *scene, const Film *film, uint32_t x, uint32_t y)
{
  return render_point(scene, film, point_colour, x, y);
}

/* The mean colour over the square of side `size` (lattice units) whose
 * bottom-left corner is the lattice point (x, y); c holds the colours at its
 * corners: bottom left, bottom right, top left, top right. With the centre's
 * colour, when the five agree (or the square is a leaf, side <= `leaf`), the
 * answer is the mean of the corners' mean and the centre; otherwise the
 * square is cut in four and the answer is the mean of the quarters'. */
static vec3s square_mean(const Scene *scene, const Film *film, uint32_t x, uint32_t y,
                         uint32_t size, uint32_t leaf, const vec3s c[4])
{
  uint32_t h = size / 2;
  const vec3s f[5] = {c[0], c[1], c[2], c[3], at(scene, film, x + h, y + h)};
  if (size <= leaf || !colours_differ(f, 5, scene->sampler.adaptive)) {
    vec3s corners = glms_vec3_add(glms_vec3_add(c[0], c[1]), glms_vec3_add(c[2], c[3]));
    return glms_vec3_add(glms_vec3_scale(corners, 0.125f), glms_vec3_scale(f[4], 0.5f));
  }
  /* The midpoints of the bottom, left, right and top sides. */
  vec3s m = f[4], b = at(scene, film, x + h, y), l = at(scene, film, x, y + h);
  vec3s r = at(scene, film, x + size, y + h), t = at(scene, film, x + h, y + size);
  const vec3s q[4][4] = {{c[0], b, l, m}, {b, c[1], m, r}, {l, m, c[2], t}, {m, r, t, c[3]}};
  vec3s sum = glms_vec3_zero();
  for (uint32_t k = 0; k < 4; k++)
    sum = glms_vec3_add(sum, square_mean(scene, film, x + (k & 1) * h, y + (k >> 1) * h, h,
                                         leaf, q[k]));
  return glms_vec3_scale(sum, 0.25f);
}
/* END SOLUTION */

vec3s antialias_pixel(const Scene *scene, const Film *film, int i, int j)
{
  /* BEGIN SOLUTION step 07 */
  if (!(scene->sampler.adaptive > 0.0f))
    return pixel_sampled(scene, i, j);
  uint32_t leaf = RENDER_LATTICE; /* halved for each factor 4 of samples past 4 */
  for (int n = scene->samples; n >= 16 && leaf > 2; n /= 4)
    leaf /= 2;
  uint32_t x = (uint32_t)i * RENDER_LATTICE, y = (uint32_t)j * RENDER_LATTICE, s = RENDER_LATTICE;
  const vec3s c[4] = {at(scene, film, x, y), at(scene, film, x + s, y),
                      at(scene, film, x, y + s), at(scene, film, x + s, y + s)};
  return square_mean(scene, film, x, y, s, leaf, c);
  /* STUB: return shade_pixel(scene, film, i, j); */
  /* END SOLUTION */
}
