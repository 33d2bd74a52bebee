/* A step's whole program around its pixel function (step 01 on): options,
 * scene, render, save, summary. README.md describes the command line. */
#include "app/app.h"

#include "threads.h"
#include <stdio.h>
#include <string.h>

#include "app/pack.h"
#include "app/aov.h"
#include "app/render.h"
#include "app/cli.h"
#include "app/image.h"
#include "app/parser.h"
#include "app/trace_pixel.h"
#include "sampler.h"

/* Say once what the step leaves out of this scene (scene_prepare's
 * info.ignored: the scene's own values and the command line's alike) or of
 * the command line's sampling options. */
static void say_ignored(const Step *step, const Options *o, unsigned ignored)
{
  static const struct {
    unsigned bit;
    const char *what;
  } parts[] = {
      {SCENE_LIGHTS, "the lights (shading starts in step 04)"},
      {SCENE_AMBIENT, "the ambient light (step 06)"},
      {SCENE_LIGHT_SHAPES, "the point lights' radius: the camera sees lights from step 06"},
      {SCENE_SAMPLES, "samples > 1 (antialiasing is step 07)"},
      {SCENE_AREA_LIGHTS, "the area lights and light_samples (step 08)"},
  };
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++)
    if (ignored & parts[k].bit)
      fprintf(stderr, "%s: ignoring %s\n", step->name, parts[k].what);
  bool sampling = step->features & SCENE_SAMPLES;
  if (!sampling && (o->sampler || o->adaptive >= 0.0f || o->seed != 1))
    fprintf(stderr, "%s: ignoring --sampler, --adaptive and --seed "
            "(antialiasing is step 07)\n", step->name);
}

static bool load(const Step *step, const Options *o, Scene *scene)
{
  scene_init(scene);
  if (o->scene_path)
    return parser_load_file(o->scene_path, scene);
  return parser_load_string(*app_default_scene_name ? app_default_scene_name : step->name,
                            app_default_scene, scene);
}

/* Command-line values win over the scene's: the film's size, the sample
 * counts and where the samples go. The counts then live in the scene alone
 * (Scene.samples, Scene.light_samples); what the step cannot render of them,
 * scene_prepare drops, whichever gave them. */
static bool override(const Step *step, const Options *o, Scene *scene)
{
  if (o->width)
    scene->width = o->width;
  if (o->height)
    scene->height = o->height;
  if ((long long)scene->width * scene->height > FILM_MAX_PIXELS) {
    fprintf(stderr, "%s: expected at most %d pixels, found %dx%d\n", step->name,
            FILM_MAX_PIXELS, scene->width, scene->height);
    return false;
  }
  if (o->samples)
    scene->samples = o->samples;
  if (o->light_samples)
    scene->light_samples = o->light_samples;
  SamplerKind kind = SAMPLER_CENTER;
  sampler_parse(o->sampler ? o->sampler : step->sampler ? step->sampler : "center", &kind);
  scene->sampler = (Sampler){.kind = kind, .seed = o->seed,
                             .adaptive = o->adaptive >= 0.0f ? o->adaptive : step->adaptive};
  return true;
}

/* The summary line. spp: the camera samples traced per pixel, their mean
 * under adaptive sampling (one per pixel before step 07). */
static void summary(const Step *step, const char *out, const Film *film,
                    const RenderStats *st)
{
  double mrays = (double)st->rays * 1e-6;
  double spp = (step->features & SCENE_SAMPLES)
                   ? (double)st->samples / ((double)film->width * film->height) : 1.0;
  printf("%s: %s %dx%d, %.4g spp, %.2f Mrays in %.3f s (%.1f Mrays/s, %d thread%s%s)\n",
         step->name, out, film->width, film->height, spp, mrays,
         st->seconds, st->seconds > 0.0 ? mrays / st->seconds : 0.0, st->threads,
         st->threads == 1 ? "" : "s", THREADS_BUILD_NOTE);
}

/* The command line's options other than --trace, --trace-format and --quiet,
 * as one string (the header of a JSON trace: how to trace the pixel again). */
static void other_args(int argc, char **argv, char *buf, size_t size)
{
  size_t len = 0;
  buf[0] = '\0';
  for (int k = 1; k < argc; k++) {
    const char *a = argv[k];
    if (!strcmp(a, "--trace") || !strcmp(a, "--trace-format")) {
      k += a[7] ? 1 : 2;
      continue;
    }
    if (!strncmp(a, "--trace-format=", 15) || !strcmp(a, "-q") || !strcmp(a, "--quiet"))
      continue;
    int n = snprintf(buf + len, size - len, "%s%s", len ? " " : "", a);
    if (n < 0 || (size_t)n >= size - len)
      return;
    len += (size_t)n;
  }
}

/* --trace X Y: one pixel's trace on stdout instead of a picture. */
static int run_trace(int argc, char **argv, const Step *step, const Options *o,
                     const Scene *scene)
{
  if (o->out_path)
    fprintf(stderr, "%s: ignoring -o (--trace prints one pixel, writes no image)\n",
            step->name);
  char args[1024];
  other_args(argc, argv, args, sizeof args);
  TraceRequest req = {.step = step->name, .features = step->features, .pixel = step->pixel,
                      .x = o->trace_x, .y = o->trace_y, .tonemap = o->tonemap,
                      .json = o->trace_json, .args = args};
  if (trace_pixel(scene, &req, stdout))
    return 0;
  return o->trace_x < scene->width && o->trace_y < scene->height ? 1 : 2;
}

/* Render the picture, or with --aov the quantity, and save it to `out`. */
static bool render_and_save(const Step *step, const Options *o, Scene *scene,
                            const RenderSettings *set, Film *film, const char *out)
{
  RenderStats st;
  Tonemap tm = o->tonemap;
  if (o->aov < 0) {
    render(scene, film, step->pixel, set, &st);
  } else {
    if (!aov_render(scene, step->pixel, set, (AovKind)o->aov, film, &st))
      return false;
    if (aov_file_is_bytes(out))
      aov_for_bytes((AovKind)o->aov, scene->samples, film);
    tm = TONEMAP_CLAMP;
  }
  bool saved = image_save(out, film->width, film->height, film->rgb, tm);
  if (saved && !o->quiet)
    summary(step, out, film, &st);
  return saved;
}

/* An --aov the step cannot draw: the Phong terms need lights (step 04). */
static bool aov_usable(const Step *step, const Options *o)
{
  if (o->aov < 0 || aov_term(o->aov) < 0 || (step->features & SCENE_LIGHTS))
    return true;
  fprintf(stderr, "%s: --aov %s: expected a step that shades (04 to 08); the Phong terms "
          "start in step 04\n", step->name, aov_name((AovKind)o->aov));
  return false;
}

int app_run(int argc, char **argv, const Step *step)
{
  Options o;
  switch (cli_parse(argc, argv, step->name, step->summary, app_default_scene_name, &o)) {
  case CLI_DONE: return 0;
  case CLI_USAGE: return 2;
  case CLI_RUN: break;
  }
  if (o.threads > 0) /* the parse and the hierarchy's build use threads too */
    omp_set_num_threads(o.threads);
  if ((o.out_path && o.trace_x < 0 && !image_format_known(o.out_path)) ||
      !aov_usable(step, &o))
    return 2;
  Scene scene;
  if (!load(step, &o, &scene))
    return 1;
  if (!override(step, &o, &scene)) {
    scene_free(&scene);
    return 2;
  }
  if (!scene_prepare(&scene, step->features) || !pack_index(&scene)) {
    scene_free(&scene);
    return 1;
  }
  say_ignored(step, &o, scene.info.ignored);
  RenderSettings set = {.threads = o.threads, .progress = !o.quiet};
  if (o.trace_x >= 0) {
    int status = run_trace(argc, argv, step, &o, &scene);
    pack_index_free(&scene);
    scene_free(&scene);
    return status;
  }
  Film film;
  char default_out[96];
  snprintf(default_out, sizeof default_out, o.aov < 0 ? "%s.png" : "%s.%s.png", step->name,
           o.aov < 0 ? "" : aov_name((AovKind)o.aov));
  const char *out = o.out_path ? o.out_path : default_out;
  int status = 1;
  if (pack_film_init(&film, scene.width, scene.height)) {
    if (render_and_save(step, &o, &scene, &set, &film, out))
      status = 0;
    film_free(&film);
  }
  pack_index_free(&scene);
  scene_free(&scene);
  return status;
}
