/* Antialiasing mistakes the step does not make, for the pictures of
 * docs/07-antialiasing.md (tools/figures/aa-mistakes.sh). Not a step.
 *   aa-mistakes same-numbers [step options]: step 07 without adaptive
 *     sampling, but every pixel draws the random numbers of pixel 0;
 *   aa-mistakes points SAMPLER N OUT.png: N samples of one pixel, drawn as
 *     dots on a 192 x 192 square with the N cells of grid and jitter;
 *   aa-mistakes zoom IN.pfm X Y W H OUT.png: the W x H pixels from column X,
 *     row Y (from the top) of IN, each shown as a 4 x 4 block. */
#include "app/app.h"
#include "app/image.h"
#include "sampler.h"
#include "scene.h"
#include "shade.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Step 07's box filter, with the mistake: the sampler is keyed by pixel 0. */
static vec3s pixel_same_numbers(const Scene *scene, const Film *film, int i, int j)
{
  FilmAccum acc = {0};
  for (int k = 0; k < scene->samples; k++) {
    vec2s s = sampler_get(scene->sampler.kind, scene->sampler.seed, 0, (uint32_t)k,
                          (uint32_t)scene->samples);
    Ray r = camera_ray(&scene->camera, ((float)i + s.x) / (float)film->width,
                       ((float)j + s.y) / (float)film->height);
    film_accum_add(&acc, shade_trace(scene, r));
  }
  return film_accum_mean(&acc);
}

enum { SIDE = 192 };

static void dot(float *rgb, int x, int y, int radius, float v)
{
  for (int dy = -radius; dy <= radius; dy++)
    for (int dx = -radius; dx <= radius; dx++) {
      int px = x + dx, py = y + dy;
      if (px >= 0 && px < SIDE && py >= 0 && py < SIDE && dx * dx + dy * dy <= radius * radius)
        for (int c = 0; c < 3; c++)
          rgb[3 * (py * SIDE + px) + c] = v;
    }
}

/* The centres of the N cells as grey dots, the samples as black discs. */
static int plot_points(const char *name, int n, const char *out)
{
  SamplerKind kind;
  if (!sampler_parse(name, &kind) || n < 1 || n > 1024) {
    fprintf(stderr, "aa-mistakes: points: expected a sampler and 1..1024 samples\n");
    return 2;
  }
  float *rgb = malloc(sizeof(float) * 3 * SIDE * SIDE);
  if (!rgb)
    return 1;
  for (int k = 0; k < 3 * SIDE * SIDE; k++)
    rgb[k] = 1.0f;
  for (int k = 0; k < n; k++) {
    vec2s cell = sampler_get(SAMPLER_GRID, 1, 0, (uint32_t)k, (uint32_t)n);
    dot(rgb, (int)(cell.x * SIDE), (int)(cell.y * SIDE), 2, 0.6f);
  }
  for (int k = 0; k < n; k++) {
    vec2s s = sampler_get(kind, 1, 0, (uint32_t)k, (uint32_t)n);
    dot(rgb, (int)(s.x * SIDE), (int)(s.y * SIDE), 4, 0.0f);
  }
  bool ok = image_save(out, SIDE, SIDE, rgb, TONEMAP_CLAMP);
  free(rgb);
  return ok ? 0 : 1;
}

enum { ZOOM = 4 };

static int zoom(const char *in, int x, int y, int w, int h, const char *out)
{
  int iw, ih;
  float *src;
  if (!image_load(in, &iw, &ih, &src))
    return 1;
  if (x < 0 || y < 0 || w < 1 || h < 1 || x + w > iw || y + h > ih) {
    fprintf(stderr, "aa-mistakes: zoom: the box is not inside the %dx%d image\n", iw, ih);
    free(src);
    return 2;
  }
  float *dst = malloc(sizeof(float) * 3 * (size_t)(w * ZOOM) * (size_t)(h * ZOOM));
  for (int j = 0; dst && j < h * ZOOM; j++)
    for (int i = 0; i < w * ZOOM; i++) {
      /* Rows count from the bottom in both buffers; y counts from the top. */
      int sj = ih - y - h + j / ZOOM, si = x + i / ZOOM;
      for (int c = 0; c < 3; c++)
        dst[3 * (j * w * ZOOM + i) + c] = src[3 * (sj * iw + si) + c];
    }
  bool ok = dst && image_save(out, w * ZOOM, h * ZOOM, dst, TONEMAP_CLAMP);
  free(src);
  free(dst);
  return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
  if (argc == 8 && !strcmp(argv[1], "zoom"))
    return zoom(argv[2], atoi(argv[3]), atoi(argv[4]), atoi(argv[5]), atoi(argv[6]), argv[7]);
  if (argc >= 2 && !strcmp(argv[1], "points"))
    return argc == 5 ? plot_points(argv[2], atoi(argv[3]), argv[4]) : 2;
  if (argc < 2 || strcmp(argv[1], "same-numbers")) {
    fprintf(stderr, "usage: aa-mistakes same-numbers [options] | points SAMPLER N OUT.png\n");
    return 2;
  }
  const Step step = {
      .name = "aa-mistakes",
      .summary = "Step 07 with the random numbers of pixel 0 in every pixel.",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES |
                  SCENE_SAMPLES,
      .sampler = "jitter",
      .pixel = pixel_same_numbers,
  };
  return app_run(argc - 1, argv + 1, &step);
}
