/* What the robust geometry costs (docs/accuracy.md, "Cost"): step 05's frame
 * (Phong, hard shadows) rendered in one process with common/'s geometry and
 * with the textbook formulas of tests/textbook.h, same shading, same threads.
 * Usage: robust-cost [RUNS [THREADS [SCENE [OUT_PREFIX]]]]. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "app/image.h"
#include "app/parser.h"
#include "app/render.h"
#include "shade.h"
#include "textbook.h"

/* The geometry of the other frames. TEXTBOOK: b^2 - c, p = o + t d, a fixed
 * offset; FLOAT_BC: the robust formula with b and c formed in float, to price
 * sphere.c's double-precision b and c (the rest as in common/). */
typedef enum Geometry { TEXTBOOK, FLOAT_BC } Geometry;

/* One shape's distance, out of line like the library's accel_instance_hit_t
 * (which then calls sphere_hit_t: one call more on the robust side). */
__attribute__((noinline)) static float other_hit_t(const Instance *in, Ray r, float tmax,
                                                   Geometry g)
{
  switch (in->shape) {
  case SHAPE_SPHERE:
    return g == TEXTBOOK ? textbook_sphere_t(&in->sphere, r, tmax)
                         : float_bc_sphere_t(&in->sphere, r, tmax);
  case SHAPE_PLANE:
    return g == TEXTBOOK ? textbook_plane_t(&in->plane, r, tmax)
                         : plane_hit_t(&in->plane, r, tmax);
  default: return scene_instance_hit_t(in, r, tmax);
  }
}

/* scene_intersect's plain loop with another geometry. */
static bool other_intersect(const Scene *sc, Ray r, float tmax, Hit *hit, Geometry g)
{
  const Instance *best = NULL;
  for (int k = 0; k < sc->n_instances; k++) {
    float t = other_hit_t(&sc->instances[k], r, tmax, g);
    if (t < tmax) {
      tmax = t;
      best = &sc->instances[k];
    }
  }
  if (!best)
    return false;
  if (g == TEXTBOOK && best->shape == SHAPE_SPHERE)
    textbook_sphere_fill(&best->sphere, r, tmax, hit);
  else if (g == TEXTBOOK && best->shape == SHAPE_PLANE)
    textbook_plane_fill(&best->plane, r, tmax, hit);
  else if (best->shape == SHAPE_SPHERE)
    sphere_hit_fill(&best->sphere, r, tmax, hit);
  else if (best->shape == SHAPE_PLANE)
    plane_hit_fill(&best->plane, r, tmax, hit);
  else
    quad_hit_fill(&best->quad, r, tmax, hit);
  hit->inst = best;
  return true;
}

static bool other_occluded(const Scene *sc, Ray r, float tmax, Geometry g)
{
  for (int k = 0; k < sc->n_shapes; k++)
    if (other_hit_t(&sc->instances[k], r, tmax, g) < tmax)
      return true;
  return false;
}

/* steps/05-shadows/shade.c's shade_trace, shade_phong and shade_incident in
 * one function, with another geometry (the robust frame is step 05's own
 * shade_trace, linked in). Inlined into each pixel function below, so g is a
 * constant there. */
static inline __attribute__((always_inline)) vec3s trace(const Scene *sc, Ray ray,
                                                         RenderCtx *ctx, Geometry g)
{
  Hit hit;
  ctx->rays++;
  if (!other_intersect(sc, ray, INFINITY, &hit, g))
    return sc->background;
  const Material *m = &sc->materials[hit.inst->material];
  vec3s c = glms_vec3_zero(), v = glms_vec3_normalize(glms_vec3_sub(ray.o, hit.p));
  for (int k = 0; k < sc->n_lights; k++) {
    vec3s l;
    float dist;
    vec3s li = light_incident(&sc->lights[k], hit.p, hit.p_err, &l, &dist);
    float n_dot_l = glms_vec3_dot(hit.n, l);
    if (!(n_dot_l > 0.0f))
      continue;
    Ray sh = g == TEXTBOOK ? textbook_spawn(&hit, l) : ray_spawn(&hit, l);
    ctx->rays++;
    if (other_occluded(sc, sh, dist * (1.0f - 0x1p-20f), g))
      continue;
    c = glms_vec3_add(c, glms_vec3_scale(glms_vec3_mul(m->diffuse, li), n_dot_l));
    if (!vec_is_zero(m->specular)) {
      vec3s r = vec_reflect(glms_vec3_negate(l), hit.n);
      float lobe = powf(fmaxf(0.0f, glms_vec3_dot(r, v)), m->shininess);
      c = glms_vec3_add(c, glms_vec3_scale(glms_vec3_mul(m->specular, li), lobe));
    }
  }
  return c;
}

static vec3s px_robust(const Scene *sc, const Film *film, int i, int j, RenderCtx *ctx)
{
  vec2s s = film_sample(film, i, j);
  return shade_trace(sc, camera_ray(&sc->camera, s.x, s.y), ctx);
}

static vec3s px_textbook(const Scene *sc, const Film *film, int i, int j, RenderCtx *ctx)
{
  vec2s s = film_sample(film, i, j);
  return trace(sc, camera_ray(&sc->camera, s.x, s.y), ctx, TEXTBOOK);
}

static vec3s px_float_bc(const Scene *sc, const Film *film, int i, int j, RenderCtx *ctx)
{
  vec2s s = film_sample(film, i, j);
  return trace(sc, camera_ray(&sc->camera, s.x, s.y), ctx, FLOAT_BC);
}

/* The frames compared: which scene (0 shipped layout, 1 plain loop) and pixel. */
static const struct Variant {
  const char *name;
  int scene;
  RenderPixelFn pixel;
} variants[] = {
    {"robust, shipped path (SIMD blocks / BVH)", 0, px_robust},
    {"robust, plain loop (RT_ACCEL=loop)", 1, px_robust},
    {"robust with float b and c, plain loop", 1, px_float_bc},
    {"textbook, plain loop", 1, px_textbook},
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
  bool ok = parser_load_file(path, sc) && scene_prepare(sc, SCENE_CAMERA | SCENE_LIGHTS) &&
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
  RenderSettings set = {.threads = threads, .seed = 1, .samples = 1, .light_samples = 1};
  static double sec[N_VAR][MAX_RUNS];
  /* Interleaved (v = 0, 1, 2, 3, 0, 1, ...): drifts of a shared machine hit
   * every variant alike. One untimed frame of each first warms the caches. */
  for (int run = -1; run < runs; run++) {
    for (int v = 0; v < N_VAR; v++) {
      RenderStats st;
      render(&sc[variants[v].scene], &film, variants[v].pixel, &set, &st);
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
  scene_free(&sc[0]);
  scene_free(&sc[1]);
  return 0;
}
