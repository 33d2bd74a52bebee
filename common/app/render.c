/* The render loop (step 01): pixels in 16 x 16 tiles, tiles shared among
 * OpenMP threads one at a time (dynamic schedule). Each pixel depends only on
 * its own coordinates and the seed, so the picture is the same whatever the
 * thread count. The rays and camera samples are counted from outside the
 * step's code: each thread renders a copy of the scene whose query table
 * counts every query, then answers it with the scene's own table.
 * docs/01-film.md; docs/performance.md on threads under load. */
#include "app/render.h"

#include "app/render_point.h"
#include "scene.h"
#include "scene_index.h"
#include "threads.h"
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

enum { TILE = 16 };

/* A thread's counting table: every query counted, then answered by the
 * scene's own (scene_closest, scene_any on `inner`). */
typedef struct CountingIndex {
  SceneIndex base; /* first member: the thread's scene.index points here */
  const Scene *inner;
  uint64_t rays, samples;
} CountingIndex;

static const Instance *counted_closest(const Scene *scene, const Ray *r, float *tmax)
{
  CountingIndex *c = (CountingIndex *)scene->index;
  vec3s eye = c->inner->camera.eye;
  c->rays++;
  c->samples += r->o.x == eye.x && r->o.y == eye.y && r->o.z == eye.z;
  return scene_closest(c->inner, r, tmax);
}

static bool counted_any(const Scene *scene, const Ray *r, float tmax)
{
  CountingIndex *c = (CountingIndex *)scene->index;
  c->rays++;
  return scene_any(c->inner, r, tmax);
}

static void draw_progress(int done, int total)
{
  int width = 40, filled = (int)((long long)done * width / total);
  fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################",
          width - filled, "", (int)((long long)done * 100 / total));
  if (done == total)
    fputs("\r\033[K", stderr);
  fflush(stderr);
}

static void render_tile(const Scene *scene, Film *film, const Film *mine, RenderPixelFn pixel,
                        RenderWatch *watch, int tile, int tiles_x)
{
  int i0 = (tile % tiles_x) * TILE, j0 = (tile / tiles_x) * TILE;
  int i1 = i0 + TILE < film->width ? i0 + TILE : film->width;
  int j1 = j0 + TILE < film->height ? j0 + TILE : film->height;
  render_memo_next_tile(mine->memo);
  for (int j = j0; j < j1; j++)
    for (int i = i0; i < i1; i++)
      film_set(film, i, j, watch ? watch->pixel(watch, scene, mine, pixel, i, j)
                                 : pixel(scene, mine, i, j));
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
  int done = 0;
  double t0 = omp_get_wtime();
  stats->rays = stats->samples = 0;
#pragma omp parallel num_threads(threads)
  {
    /* Each thread's own scene, counting table and film (its memo), on its
     * own stack: the counters every query increments are never shared. */
    CountingIndex count = {.base = {.closest = counted_closest, .any = counted_any},
                           .inner = scene};
    Scene counted = *scene;
    counted.index = &count.base;
    Film mine = *film;
    mine.memo = render_memo_new();
    RenderWatch *watch = set->watch ? set->watch[omp_get_thread_num()] : NULL;
#pragma omp for schedule(dynamic, 1)
    for (int tile = 0; tile < tiles; tile++) {
      render_tile(&counted, film, &mine, pixel, watch, tile, tiles_x);
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
    free(mine.memo);
#pragma omp critical(stats)
    {
      stats->rays += count.rays;
      stats->samples += count.samples;
    }
  }
  stats->seconds = omp_get_wtime() - t0;
  stats->threads = threads;
}
