/* Where step 07's adaptive sampling puts its samples, for the picture of
 * docs/07-antialiasing.md, "Adaptive sampling". Not a step: it compiles
 * common/antialias.c in (so the pixels are the step's own), counts every distinct
 * point render_point traces inside each pixel's square (its bottom and left
 * sides included: each point counts once, in one pixel), and draws the
 * counts: dark blue 2 (a corner and the centre), up to white at the largest
 * count. tools/figures/aa-mistakes.sh runs it.
 * Usage: aa-samples W H SAMPLES THRESHOLD OUT.png */
#include <stdio.h>
#include <stdlib.h>

#include "index/accel.h"
#include "app/app.h"
#include "app/image.h"
#include "app/parser.h"
#include "app/render.h"
#include "app/render_point.h"
#include "sampler.h"
#include "shade.h"

/* common/antialias.c below calls render_point: it calls this instead, which
 * counts the point and calls render_point. */
static vec3s counting_point(const Scene *scene, const Film *film, RenderPointFn colour,
                            uint32_t x, uint32_t y);
#define render_point counting_point
#define antialias_pixel pixel
#include "../../common/antialias.c"
#undef antialias_pixel
#undef render_point

/* The distinct lattice points traced (one thread: no locking), as x << 32 | y
 * + 1 in an open-addressed table, and the count per pixel. */
enum { SEEN_BITS = 24 };
static uint64_t *seen;
static uint32_t *counts;
static int film_w, film_h;

static void count(uint32_t x, uint32_t y)
{
  uint64_t key = ((uint64_t)x << 32 | y) + 1, h = key * 0x9e3779b97f4a7c15ull;
  for (size_t k = h >> (64 - SEEN_BITS);; k = (k + 1) & ((1u << SEEN_BITS) - 1)) {
    if (seen[k] == key)
      return;
    if (!seen[k]) {
      seen[k] = key;
      break;
    }
  }
  int i = (int)(x / RENDER_LATTICE), j = (int)(y / RENDER_LATTICE);
  if (i < film_w && j < film_h) /* not the film's right and top edges */
    counts[j * film_w + i]++;
}

static vec3s counting_point(const Scene *scene, const Film *film, RenderPointFn colour,
                            uint32_t x, uint32_t y)
{
  count(x, y);
  return render_point(scene, film, colour, x, y);
}

/* Dark blue at 2 samples, through red and yellow, to white at `top`. */
static vec3s ramp(uint32_t n, uint32_t top)
{
  float t = n <= 2 ? 0.0f : logf((float)n / 2.0f) / logf((float)top / 2.0f);
  t = t < 1.0f ? t : 1.0f;
  return vec_make(fminf(1.0f, 0.15f + 2.0f * t), fmaxf(0.0f, 2.0f * t - 0.6f),
                  t < 0.5f ? 0.4f - 0.8f * t : 2.0f * t - 1.0f);
}

int main(int argc, char **argv)
{
  if (argc != 6) {
    fprintf(stderr, "usage: aa-samples W H SAMPLES THRESHOLD OUT.png\n");
    return 2;
  }
  Scene scene;
  scene_init(&scene);
  if (!parser_load_string(app_default_scene_name, app_default_scene, &scene))
    return 1;
  scene.width = film_w = atoi(argv[1]);
  scene.height = film_h = atoi(argv[2]);
  scene.samples = atoi(argv[3]);
  if (film_w < 1 || film_h < 1 || scene.samples < 1 ||
      !scene_prepare(&scene, SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT |
                                 SCENE_LIGHT_SHAPES | SCENE_SAMPLES) ||
      !accel_build(&scene))
    return 1;
  scene.sampler = (Sampler){.kind = SAMPLER_SOBOL, .seed = 1,
                            .adaptive = strtof(argv[4], NULL)};
  RenderSettings set = {.threads = 1};
  Film film;
  seen = calloc((size_t)1 << SEEN_BITS, sizeof *seen);
  counts = calloc((size_t)film_w * (size_t)film_h, sizeof *counts);
  if (!seen || !counts || !film_init(&film, film_w, film_h))
    return 1;
  RenderStats st;
  render(&scene, &film, pixel, &set, &st);
  uint32_t top = 3;
  for (int k = 0; k < film_w * film_h; k++)
    top = counts[k] > top ? counts[k] : top;
  for (int j = 0; j < film_h; j++)
    for (int i = 0; i < film_w; i++)
      film_set(&film, i, j, ramp(counts[j * film_w + i], top));
  bool ok = image_save(argv[5], film_w, film_h, film.rgb, TONEMAP_CLAMP);
  printf("aa-samples: %s %dx%d: %.2f samples per pixel on average, at most %u\n", argv[5],
         film_w, film_h, (double)st.samples / (film_w * film_h), top);
  film_free(&film);
  accel_free(&scene);
  scene_free(&scene);
  free(seen);
  free(counts);
  return ok ? 0 : 1;
}
