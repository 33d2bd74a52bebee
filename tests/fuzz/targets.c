/* The fuzzing targets (docs/reliability.md, "Fuzzing"): the scene reader with
 * scene preparation and the acceleration structure, the command line, and a
 * tiny render through step 08's shading. Bad input is expected (the program's
 * messages go to stderr); a bug aborts. */
#include "fuzz.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "index/accel.h"
#include "app/app.h"
#include "app/cli.h"
#include "app/image.h"
#include "app/parser.h"
#include "app/render.h"
#include "app/parser_state.h"
#include "reader/sphere_line.h"
#include "sampler.h"

static Step step08;

int fuzz_app_run(int argc, char **argv, const Step *step)
{
  (void)argc;
  (void)argv;
  step08 = *step;
  return 0;
}

/* Step 08's description, from its own main. */
static const Step *step08_get(void)
{
  if (!step08.pixel) {
    char name[] = "fuzz", *argv[] = {name, NULL};
    fuzz_step08_main(1, argv);
  }
  return &step08;
}

static void bug(const char *what)
{
  fprintf(stderr, "fuzz: %s\n", what);
  fflush(stderr);
  abort();
}

/* The index must answer as the plain loop over the instances does. */
static void same_answers(Scene *s, Ray r)
{
  const SceneIndex *index = s->index;
  Hit a, b;
  bool ha = scene_intersect(s, r, INFINITY, &a), oa = scene_occluded(s, r, 1e30f);
  s->index = NULL;
  bool hb = scene_intersect(s, r, INFINITY, &b), ob = scene_occluded(s, r, 1e30f);
  s->index = index;
  if (ha != hb || (ha && (a.inst != b.inst || a.t != b.t)))
    bug("the index's closest hit differs from the plain loop's");
  if (oa != ob)
    bug("the index's any-hit answer differs from the plain loop's");
  if (ha) {
    bool ta = scene_occluded(s, r, a.t);
    s->index = NULL;
    bool tb = scene_occluded(s, r, a.t);
    s->index = index;
    if (ta != tb)
      bug("the index's any-hit answer up to the closest hit differs from the loop's");
  }
}

/* The text parsed by the general path alone (the speed pack's sphere lines
 * off) must give what the parse with them gave: the same verdict and the
 * same shapes, each with its material. */
static void same_without_sphere_lines(const uint8_t *data, size_t size, bool ok,
                                      const Scene *fast)
{
  Scene p;
  scene_init(&p);
  sphere_line_on = false;
  bool ok_p = parser_load_text("fuzz.scene", (const char *)data, size, &p);
  sphere_line_on = true;
  if (ok_p != ok)
    bug("the pack's sphere lines and the general path disagree on the text's validity");
  if (!ok)
    return;
  if (p.n_instances != fast->n_instances || p.n_shapes != fast->n_shapes ||
      p.n_materials != fast->n_materials || p.n_lights != fast->n_lights)
    bug("the pack's sphere lines count other shapes, materials or lights");
  for (int k = 0; k < p.n_instances; k++)
    if (p.instances[k].shape != fast->instances[k].shape ||
        p.instances[k].material != fast->instances[k].material ||
        memcmp(&p.instances[k].sphere, &fast->instances[k].sphere, sizeof p.instances[k].sphere))
      bug("the pack's sphere lines give a shape another shape, place or material");
  scene_free(&p);
}

void fuzz_scene(const uint8_t *data, size_t size)
{
  static const char *const layouts[] = {"bvh", "flat", ""};
  setenv("RT_ACCEL", layouts[size % 3], 1); /* any sphere count in each layout */
  Scene s;
  scene_init(&s);
  bool ok = parser_load_text("fuzz.scene", (const char *)data, size, &s);
  same_without_sphere_lines(data, size, ok, &s);
  if (!ok)
    return;
  if (scene_prepare(&s, step08_get()->features) && accel_build(&s)) {
    for (int k = 0; k < 25; k++)
      same_answers(&s, camera_ray(&s.camera, (float)(k % 5) / 4.0f, (float)(k / 5) / 4.0f));
  }
  accel_free(&s);
  scene_free(&s);
}

void fuzz_cli(const uint8_t *data, size_t size)
{
  char *buf = malloc(size + 1), name[] = "fuzz", *argv[66];
  if (!buf)
    return;
  memcpy(buf, data, size);
  buf[size] = '\0';
  int argc = 0;
  argv[argc++] = name;
  for (char *p = buf; p <= buf + size && argc < 65; p += strlen(p) + 1)
    argv[argc++] = p;
  argv[argc] = NULL;
  Options o;
  if (cli_parse(argc, argv, "fuzz", "a summary", "scenes/spheres.scene", &o) == CLI_RUN &&
      o.out_path)
    image_format_known(o.out_path);
  free(buf);
}

static int smaller(int a, int b)
{
  return a < b ? a : b;
}

/* Every pixel a number, and its bytes under every tone map. */
static void check_film(const Film *film)
{
  for (int k = 0; k < film->width * film->height * 3; k++) {
    if (isnan(film->rgb[k]))
      bug("a pixel is NaN");
    for (int tm = 0; tm < 3; tm++)
      (void)film_to_byte(film->rgb[k], (Tonemap)tm);
  }
}

void fuzz_render(const uint8_t *data, size_t size)
{
  static const char *const samplers[] = {"center", "grid", "random", "jitter", "sobol"};
  const Step *step = step08_get();
  Scene s;
  scene_init(&s);
  if (!parser_load_text("fuzz.scene", (const char *)data, size, &s))
    return;
  s.width = smaller(s.width, 12);
  s.height = smaller(s.height, 9);
  s.samples = smaller(s.samples, 4);
  s.light_samples = smaller(s.light_samples, 4);
  Film film;
  if (scene_prepare(&s, step->features) && accel_build(&s) &&
      film_init(&film, s.width, s.height)) {
    SamplerKind kind = SAMPLER_CENTER;
    sampler_parse(samplers[size % 5], &kind);
    s.sampler = (Sampler){.kind = kind, .seed = 1, .adaptive = size % 2 ? step->adaptive : 0.0f};
    RenderSettings set = {.threads = 1, .progress = false};
    RenderStats st;
    render(&s, &film, step->pixel, &set, &st);
    check_film(&film);
    film_free(&film);
  }
  accel_free(&s);
  scene_free(&s);
}
