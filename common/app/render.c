/* The render loop (step 01): pixels in 16 x 16 tiles, tiles shared among
 * OpenMP threads one at a time (dynamic schedule). Each pixel depends only on
 * its own coordinates and the seed, so the picture is the same whatever the
 * thread count. docs/01-film.md; docs/performance.md on threads under load. */
#include "app/render.h"

#include "threads.h"
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

enum { TILE = 16 };

static void draw_progress(int done, int total)
{
  int width = 40, filled = (int)((long long)done * width / total);
  fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################",
          width - filled, "", (int)((long long)done * 100 / total));
  if (done == total)
    fputs("\r\033[K", stderr);
  fflush(stderr);
}

static void render_tile(const Scene *scene, Film *film, RenderPixelFn pixel,
                        int tile, int tiles_x, RenderCtx *ctx)
{
  int i0 = (tile % tiles_x) * TILE, j0 = (tile / tiles_x) * TILE;
  int i1 = i0 + TILE < film->width ? i0 + TILE : film->width;
  int j1 = j0 + TILE < film->height ? j0 + TILE : film->height;
  ctx->tile++; /* render_point forgets the last tile's points: what a tile
                * traces never depends on which tiles the thread did before */
  for (int j = j0; j < j1; j++)
    for (int i = i0; i < i1; i++) {
      ctx->pixel = (uint32_t)j * (uint32_t)film->width + (uint32_t)i;
      ctx->sample = 0;
      film_set(film, i, j, pixel(scene, film, i, j, ctx));
    }
}

int render_threads(const RenderSettings *set)
{
#ifndef _OPENMP
  return 1; /* the pragmas below are ignored: one thread, whatever was asked */
#endif
  int threads = set->threads > 0 ? set->threads : omp_get_max_threads();
  return threads < RENDER_MAX_THREADS ? threads : RENDER_MAX_THREADS;
}

void render(const Scene *scene, Film *film, RenderPixelFn pixel,
            const RenderSettings *set, RenderStats *stats)
{
  int threads = render_threads(set);
  int tiles_x = (film->width + TILE - 1) / TILE;
  int tiles = tiles_x * ((film->height + TILE - 1) / TILE);
  bool progress = set->progress && isatty(STDERR_FILENO);
  /* One cache line per thread (RenderCtx is 64 bytes): the counters every ray
   * increments never share a line between threads. */
  _Alignas(64) RenderCtx ctx[RENDER_MAX_THREADS] = {{0}};
  int done = 0;
  double t0 = omp_get_wtime();
#pragma omp parallel num_threads(threads)
  {
    RenderCtx *mine = &ctx[omp_get_thread_num()];
    mine->set = set;
    mine->trace = set->traces ? set->traces[omp_get_thread_num()] : NULL;
#pragma omp for schedule(dynamic, 1)
    for (int tile = 0; tile < tiles; tile++) {
      render_tile(scene, film, pixel, tile, tiles_x, mine);
      if (progress) {
        int now;
#pragma omp atomic capture
        now = ++done;
        if (omp_get_thread_num() == 0 || now == tiles) {
#pragma omp critical(progress)
          draw_progress(now, tiles);
        }
      }
    }
  }
  stats->seconds = omp_get_wtime() - t0;
  for (int k = 0; k < threads; k++)
    free(ctx[k].memo);
  stats->threads = threads;
  stats->rays = stats->samples = 0;
  for (int k = 0; k < threads; k++) {
    stats->rays += ctx[k].rays;
    stats->samples += ctx[k].samples;
  }
}
