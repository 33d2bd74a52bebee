/* What every step's main does: parse the command line, load the scene (or the
 * step's default one), render it with the step's pixel function, save the
 * film, print a summary line. Introduced in step 01; README.md. */
#ifndef RT_APP_H
#define RT_APP_H

#include "vec.h"

typedef struct Scene Scene; /* scene.h */
typedef struct Film Film;   /* film.h */

typedef struct Step {
  const char *name;      /* "04-phong" */
  const char *summary;   /* one line for --help */
  unsigned features;     /* SceneFeature bits the step renders */
  const char *sampler;   /* default sampler name, NULL when the step has none */
  float adaptive;        /* default --adaptive threshold, 0 = off */
  /* The step's per-pixel work (app/render.h's RenderPixelFn): the colour of
   * pixel (i, j), i from the left, j from the bottom. */
  vec3s (*pixel)(const Scene *scene, const Film *film, int i, int j);
} Step;

/* The default scene text, compiled in from scenes/ by tools/build/scene2c.sh. */
extern const char app_default_scene[];
extern const char app_default_scene_name[];

/* Run the step; returns main's exit status (0 ok, 1 failure, 2 usage). */
int app_run(int argc, char **argv, const Step *step);

#endif
