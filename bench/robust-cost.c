/* What the robust geometry costs (docs/accuracy.md, "Cost"): step 05's frame
 * (Phong, hard shadows) rendered in one process through step 05's own
 * shade_trace, with common/'s intersection tests and with the textbook ones
 * of tests/textbook.h (installed as the scene's index), same threads. The hit
 * records (*_fill) and the shadow rays' start (ray_spawn) are step 05's in
 * every frame: only the tests differ.
 * Usage: robust-cost [RUNS [THREADS [SCENE [OUT_PREFIX]]]]. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "index/accel.h"
#include "app/image.h"
#include "app/parser.h"
#include "app/render.h"
#include "shade.h"
#include "textbook.h"

/* The other frames' intersection tests: TEXTBOOK (b^2 - c) or FLOAT_BC (the
 * robust formula with b and c formed in float, to price sphere.c's
 * double-precision b and c); planes and quads keep the library's. */
typedef enum Geometry { TEXTBOOK, FLOAT_BC } Geometry;

static float other_hit_t(const Instance *in, Ray r, float tmax, Geometry g)
{
  if (in->shape == SHAPE_SPHERE)
    return g == TEXTBOOK ? textbook_sphere_t(&in->sphere, r, tmax)
                         : float_bc_sphere_t(&in->sphere, r, tmax);
  if (in->shape == SHAPE_PLANE && g == TEXTBOOK)
    return textbook_plane_t(&in->plane, r, tmax);
  return scene_instance_hit_t(in, r, tmax);
}

/* A SceneIndex that tests every instance in order, as scene.c's plain loop,
 * with geometry g: installed as scene->index, it changes only the tests;
 * the frame is still step 05's shade_trace, the hit records its *_fill. */
static const Instance *other_closest(const Scene *sc, Ray r, float *tmax, Geometry g)
{
  const Instance *best = NULL;
  for (int k = 0; k < sc->n_instances; k++) {
    float t = other_hit_t(&sc->instances[k], r, *tmax, g);
    if (t < *tmax) {
      *tmax = t;
      best = &sc->instances[k];
    }
  }
  return best;
}

static bool other_any(const Scene *sc, Ray r, float tmax, Geometry g)
{
  for (int k = 0; k < sc->n_shapes; k++)
    if (other_hit_t(&sc->instances[k], r, tmax, g) < tmax)
      return true;
  return false;
}

static const Instance *textbook_closest(const Scene *sc, const Ray *r, float *tmax)
{
  return other_closest(sc, *r, tmax, TEXTBOOK);
}
static bool textbook_any(const Scene *sc, const Ray *r, float tmax)
{
  return other_any(sc, *r, tmax, TEXTBOOK);
}
static const Instance *float_bc_closest(const Scene *sc, const Ray *r, float *tmax)
{
  return other_closest(sc, *r, tmax, FLOAT_BC);
}
static bool float_bc_any(const Scene *sc, const Ray *r, float tmax)
{
  return other_any(sc, *r, tmax, FLOAT_BC);
}
static const SceneIndex textbook_index = {textbook_closest, textbook_any};
static const SceneIndex float_bc_index = {float_bc_closest, float_bc_any};


/* The frames compared: which scene (0 shipped index, 1 plain loop) and which
 * index replaces the plain loop's (NULL: scene.c's own loop). */
static const struct Variant {
  const char *name;
  int scene;
  const SceneIndex *index;
} variants[] = {
    {"robust, shipped index (one leaf / BVH)", 0, NULL},
    {"robust, plain loop (RT_ACCEL=loop)", 1, NULL},
    {"robust with float b and c, plain loop", 1, &float_bc_index},
    {"textbook, plain loop", 1, &textbook_index},
};
enum { N_VAR = sizeof variants / sizeof variants[0], MAX_RUNS = 101 };

static int cmp_double(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static bool load(const char *path, Scene *sc, const char *layout)
{
  scene_init(sc);
  if (layout)
    setenv("RT_ACCEL", layout, 1);
  else
    unsetenv("RT_ACCEL");
  bool ok = parser_load_file(path, sc) && scene_prepare(sc, SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS) &&
            accel_build(sc);
  unsetenv("RT_ACCEL");
  return ok;
}

int main(int argc, char **argv)
{
  int runs = argc > 1 ? atoi(argv[1]) : 11, threads = argc > 2 ? atoi(argv[2]) : 1;
  const char *path = argc > 3 ? argv[3] : "scenes/spheres.scene";
  const char *prefix = argc > 4 ? argv[4] : NULL;
  if (runs < 1 || runs > MAX_RUNS || threads < 1 || threads > RENDER_MAX_THREADS) {
    fprintf(stderr, "usage: robust-cost [RUNS 1..%d [THREADS [SCENE [OUT_PREFIX]]]]\n", MAX_RUNS);
    return 2;
  }
  Scene sc[2];
  if (!load(path, &sc[0], NULL) || !load(path, &sc[1], "loop"))
    return 1;
  Film film;
  if (!film_init(&film, sc[0].width, sc[0].height))
    return 1;
  RenderSettings set = {.threads = threads};
  static double sec[N_VAR][MAX_RUNS];
  /* Interleaved (v = 0, 1, 2, 3, 0, 1, ...): drifts of a shared machine hit
   * every variant alike. One untimed frame of each first warms the caches. */
  for (int run = -1; run < runs; run++) {
    for (int v = 0; v < N_VAR; v++) {
      RenderStats st;
      Scene view = sc[variants[v].scene];
      if (variants[v].index)
        view.index = variants[v].index;
      render(&view, &film, shade_pixel, &set, &st);
      if (run >= 0)
        sec[v][run] = st.seconds;
      else if (prefix) {
        char out[512];
        snprintf(out, sizeof out, "%s-%d.pfm", prefix, v);
        image_save(out, film.width, film.height, film.rgb, TONEMAP_SRGB);
      }
    }
  }
  double med[N_VAR];
  for (int v = 0; v < N_VAR; v++) {
    qsort(sec[v], (size_t)runs, sizeof(double), cmp_double);
    med[v] = runs % 2 ? sec[v][runs / 2] : 0.5 * (sec[v][runs / 2 - 1] + sec[v][runs / 2]);
  }
  printf("%s, %dx%d, %d thread%s, median of %d frames\n\n", path, film.width, film.height,
         threads, threads > 1 ? "s" : "", runs);
  printf("| geometry | median ms | min ms | max ms | / textbook |\n|---|---|---|---|---|\n");
  for (int v = 0; v < N_VAR; v++)
    printf("| %s | %.2f | %.2f | %.2f | %.3f |\n", variants[v].name, 1e3 * med[v],
           1e3 * sec[v][0], 1e3 * sec[v][runs - 1], med[v] / med[N_VAR - 1]);
  film_free(&film);
  accel_free(&sc[0]);
  accel_free(&sc[1]);
  scene_free(&sc[0]);
  scene_free(&sc[1]);
  return 0;
}
