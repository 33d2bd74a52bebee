/* The render loop: every pixel of the film through a step's pixel function,
 * in parallel over tiles (OpenMP threads), deterministic whatever the thread
 * count, with a progress bar on a terminal. Introduced in step 01;
 * docs/01-film.md. */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stdbool.h>
#include <stdint.h>
#include "film.h"
#include "sampler.h"
#include "scene.h"

enum { RENDER_MAX_THREADS = 256 };

/* How to render a scene. What to render, the sample counts included
 * (scene->samples, scene->light_samples), is the scene's. */
typedef struct RenderSettings {
  int threads;        /* 0: one per online core; at most RENDER_MAX_THREADS */
  uint32_t seed;      /* keys every random number (with pixel and sample) */
  SamplerKind sampler; /* sampling pattern (steps 07, 08) */
  float adaptive;     /* adaptive sampling threshold, 0 = off (steps 07, 08) */
  bool progress;      /* draw a progress bar on stderr */
  struct TraceEvents **traces; /* --aov: one per thread (ctx->trace), else NULL */
} RenderSettings;

struct RenderMemo;

/* Per-thread state handed to the pixel function. */
typedef struct RenderCtx {
  const RenderSettings *set;
  uint64_t rays;      /* rays traced by this thread: the step's code counts */
  uint64_t samples;   /* camera samples taken by this thread */
  uint32_t pixel;     /* j * width + i of the pixel being rendered */
  uint32_t sample;    /* index of the camera sample being traced (steps 07-08
                       * set it; shading keys its random numbers on both) */
  struct TraceEvents *trace; /* --trace, --aov: where the hooks of
                              * common/app/trace.h write; NULL when off */
  struct RenderMemo *memo; /* render_point's colours of this tile (owned by
                            * render; NULL until the first call) */
  uint32_t tile;      /* tiles this thread has started: render_point's memo
                       * keeps the colours of the current one only */
} RenderCtx;

/* A step's per-pixel work: the colour of pixel (i, j) (i from the left, j from
 * the bottom), linear RGB. Must depend only on its arguments. */
typedef vec3s (*RenderPixelFn)(const Scene *scene, const Film *film, int i,
                               int j, RenderCtx *ctx);

typedef struct RenderStats {
  double seconds;     /* wall time of the loop */
  uint64_t rays, samples;
  int threads;
} RenderStats;

/* The number of threads render() runs with these settings. */
int render_threads(const RenderSettings *set);

/* Fill every pixel of `film` with `pixel`. */
void render(const Scene *scene, Film *film, RenderPixelFn pixel,
            const RenderSettings *set, RenderStats *stats);

#endif
