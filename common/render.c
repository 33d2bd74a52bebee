/* The render loop (step 01): pixels in 16 x 16 tiles, handed out one at a
 * time to the threads. Each pixel depends only on its own coordinates and the
 * seed, so the picture is the same whatever the thread count. docs/01-film.md. */
#include "render.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <time.h>
#include <unistd.h>

enum { TILE = 16 };

/* What the threads share. The next tile is one atomic counter (tiles are
 * taken in order as threads free up: dynamic scheduling, one tile at a time).
 * Plain POSIX threads rather than OpenMP: libgomp's default wait policy spins
 * for milliseconds in a thread that waits, and on a shared 2-core machine that
 * spinning took the core the last busy thread needed (2 threads rendered
 * slower than 1 while other jobs ran; docs/performance.md). A joined thread
 * sleeps. */
typedef struct Job {
  const Scene *scene;
  Film *film;
  RenderPixelFn pixel;
  int tiles, tiles_x;
  bool progress;
  atomic_int next, done;
  pthread_mutex_t draw; /* one progress bar drawn at a time */
} Job;

typedef struct Worker {
  Job *job;
  RenderCtx *ctx;
  bool main; /* the calling thread: it draws the progress bar */
} Worker;

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
  for (int j = j0; j < j1; j++)
    for (int i = i0; i < i1; i++) {
      ctx->pixel = (uint32_t)j * (uint32_t)film->width + (uint32_t)i;
      ctx->sample = 0;
      film_set(film, i, j, pixel(scene, film, i, j, ctx));
    }
}

static void *work(void *arg)
{
  Worker *w = arg;
  Job *job = w->job;
  for (;;) {
    int tile = atomic_fetch_add_explicit(&job->next, 1, memory_order_relaxed);
    if (tile >= job->tiles)
      return NULL;
    render_tile(job->scene, job->film, job->pixel, tile, job->tiles_x, w->ctx);
    if (job->progress) {
      int now = atomic_fetch_add(&job->done, 1) + 1;
      if (w->main || now == job->tiles) {
        pthread_mutex_lock(&job->draw);
        draw_progress(now, job->tiles);
        pthread_mutex_unlock(&job->draw);
      }
    }
  }
}

static double seconds_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void render(const Scene *scene, Film *film, RenderPixelFn pixel,
            const RenderSettings *set, RenderStats *stats)
{
  long cores = sysconf(_SC_NPROCESSORS_ONLN);
  int threads = set->threads > 0 ? set->threads : cores > 0 ? (int)cores : 1;
  if (threads > RENDER_MAX_THREADS)
    threads = RENDER_MAX_THREADS;
  int tiles_x = (film->width + TILE - 1) / TILE;
  Job job = {.scene = scene, .film = film, .pixel = pixel, .tiles_x = tiles_x,
             .tiles = tiles_x * ((film->height + TILE - 1) / TILE),
             .progress = set->progress && isatty(STDERR_FILENO)};
  atomic_init(&job.next, 0);
  atomic_init(&job.done, 0);
  pthread_mutex_init(&job.draw, NULL);
  /* One cache line per thread: RenderCtx is 64 bytes, and aligned so the
   * counters every ray increments never share a line between threads. */
  _Alignas(64) RenderCtx ctx[RENDER_MAX_THREADS] = {{0}};
  Worker workers[RENDER_MAX_THREADS];
  pthread_t ids[RENDER_MAX_THREADS];
  bool started[RENDER_MAX_THREADS] = {false};
  double t0 = seconds_now();
  for (int k = 0; k < threads; k++) {
    ctx[k].set = set;
    workers[k] = (Worker){.job = &job, .ctx = &ctx[k], .main = k == 0};
  }
  /* A thread that cannot start is no error: the others take its tiles. */
  for (int k = 1; k < threads; k++)
    started[k] = pthread_create(&ids[k], NULL, work, &workers[k]) == 0;
  work(&workers[0]);
  for (int k = 1; k < threads; k++)
    if (started[k])
      pthread_join(ids[k], NULL);
  stats->seconds = seconds_now() - t0;
  pthread_mutex_destroy(&job.draw);
  stats->threads = threads;
  stats->rays = stats->samples = 0;
  for (int k = 0; k < threads; k++) {
    stats->rays += ctx[k].rays;
    stats->samples += ctx[k].samples;
  }
}
