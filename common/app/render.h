/* The render loop: every pixel of the film through a step's pixel function,
 * in parallel over tiles (OpenMP threads), deterministic whatever the thread
 * count, with a progress bar on a terminal. Each thread renders a copy of
 * the scene whose query table counts the queries and answers them with the
 * scene's own. Introduced in step 01; docs/01-film.md. */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stdbool.h>
#include <stdint.h>
#include "film.h"
#include "scene.h"

enum { RENDER_MAX_THREADS = 256 };

/* A step's per-pixel work: the colour of pixel (i, j) (i from the left, j from
 * the bottom), linear RGB. Must depend only on its arguments. */
typedef vec3s (*RenderPixelFn)(const Scene *scene, const Film *film, int i, int j);

/* Something that renders each pixel in the pixel function's place, calling
 * it itself (--aov's recorders, app/aov.c): one per thread. */
typedef struct RenderWatch {
  vec3s (*pixel)(struct RenderWatch *self, const Scene *scene, const Film *film,
                 RenderPixelFn pixel, int i, int j);
} RenderWatch;

/* How to render a scene. What to render, the samples and where they go
 * included (scene->samples, scene->light_samples, scene->sampler), is the
 * scene's. */
typedef struct RenderSettings {
  int threads;        /* 0: one per online core; at most RENDER_MAX_THREADS */
  bool progress;      /* draw a progress bar on stderr */
  RenderWatch *const *watch; /* one per thread, or NULL */
} RenderSettings;

typedef struct RenderStats {
  double seconds;     /* wall time of the loop */
  uint64_t rays;      /* queries answered: closest-hit and any-hit */
  uint64_t samples;   /* closest-hit queries from the camera's eye */
  int threads;
} RenderStats;

/* The number of threads render() runs with these settings. */
int render_threads(const RenderSettings *set);

/* Fill every pixel of `film` with `pixel`. */
void render(const Scene *scene, Film *film, RenderPixelFn pixel,
            const RenderSettings *set, RenderStats *stats);

#endif
