/* Shadow tests the steps do not use: the lecture's closest-hit version (to
 * time it against step 05's any-hit query) and the typical mistakes pictured
 * in docs/05-shadows.md and docs/06-ambient.md. Not a step; shading as in
 * common/shade.c, phong.c and shadow.c at step 06, only the visibility test changes.
 * Usage: build/bin/mistakes VARIANT [the steps' options], VARIANT one of
 * lecture, closest, no-offset, epsilon=E, no-tmax, light-shadows. */
#include "app/app.h"
#include "film.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum Variant {
  LECTURE,       /* closest hit, for every light, even those behind the surface */
  CLOSEST,       /* closest hit, only for lights in front of the surface */
  NO_OFFSET,     /* any-hit from the hit point itself */
  EPSILON,       /* any-hit from p + epsilon n: one fixed offset for every scale */
  NO_TMAX,       /* any-hit without stopping at the light */
  LIGHT_SHADOWS, /* lights' shapes block shadow rays too */
} Variant;

/* Set once by main before rendering; read-only while the threads run. */
static Variant variant;
static float epsilon;

/* Is light k visible from the hit? Step 05 is: n.l > 0, then
 * !scene_occluded(scene, ray_spawn(hit, l), dist * (1 - 2^-20)). */
static bool visible(const Scene *scene, int k, const Hit *hit, vec3s l, float dist)
{
  if (variant != LECTURE && !(glms_vec3_dot(hit->n, l) > 0.0f))
    return true; /* no ray: the Phong loop skips this light anyway */
  Ray r = ray_spawn(hit, l);
  if (variant == NO_OFFSET)
    r.o = hit->p;
  if (variant == EPSILON)
    r.o = glms_vec3_add(hit->p, glms_vec3_scale(hit->n, epsilon));
  float tmax = dist * (1.0f - 0x1p-20f);
  Hit first;
  switch (variant) {
  case LECTURE:
  case CLOSEST:
    /* The lecture: visible when the first thing hit is the light itself (its
     * shape), or nothing before it (a point light without a shape). */
    if (!scene_intersect(scene, r, INFINITY, &first))
      return true;
    return first.light == k || first.t >= tmax;
  case NO_TMAX: return !scene_occluded(scene, r, INFINITY);
  case LIGHT_SHADOWS: return !scene_intersect(scene, r, tmax, &first);
  default: return !scene_occluded(scene, r, tmax);
  }
}

/* Step 06's Phong with ambient, the visibility test above. */
static vec3s phong(const Scene *scene, const Hit *hit, vec3s eye)
{
  const Material *m = &scene->materials[hit->material];
  vec3s c = scene->info.ambient ? glms_vec3_mul(m->ambient, scene->ambient) : glms_vec3_zero();
  vec3s v = glms_vec3_normalize(glms_vec3_sub(eye, hit->p));
  for (int k = 0; k < scene->n_lights; k++) {
    vec3s l;
    float dist;
    vec3s li = light_incident(&scene->lights[k], hit->p, hit->p_err, &l, &dist);
    if (!visible(scene, k, hit, l, dist))
      continue;
    float n_dot_l = glms_vec3_dot(hit->n, l);
    if (!(n_dot_l > 0.0f))
      continue;
    c = glms_vec3_add(c, glms_vec3_scale(glms_vec3_mul(m->diffuse, li), n_dot_l));
    vec3s r = vec_reflect(glms_vec3_negate(l), hit->n);
    float lobe = powf(fmaxf(0.0f, glms_vec3_dot(r, v)), m->shininess);
    c = glms_vec3_add(c, glms_vec3_scale(glms_vec3_mul(m->specular, li), lobe));
  }
  return c;
}

static vec3s pixel(const Scene *scene, const Film *film, int i, int j)
{
  vec2s s = film_sample(film, i, j);
  Ray ray = camera_ray(&scene->camera, s.x, s.y);
  Hit hit;
  if (!scene_intersect(scene, ray, INFINITY, &hit))
    return scene->background;
  if (hit.light >= 0)
    return glms_vec3_divs(scene->lights[hit.light].power, hit.t * hit.t);
  return phong(scene, &hit, ray.o);
}

static bool parse_variant(const char *arg)
{
  static const char *const names[] = {"lecture", "closest", "no-offset", "epsilon=",
                                      "no-tmax", "light-shadows"};
  for (int k = 0; k < 6; k++) {
    size_t n = strlen(names[k]);
    if (k == EPSILON ? strncmp(arg, names[k], n) != 0 : strcmp(arg, names[k]) != 0)
      continue;
    variant = (Variant)k;
    if (k != EPSILON)
      return true;
    char *end;
    epsilon = strtof(arg + n, &end);
    return *end == '\0' && epsilon > 0.0f && isfinite(epsilon);
  }
  return false;
}

int main(int argc, char **argv)
{
  if (argc < 2 || !parse_variant(argv[1])) {
    fprintf(stderr, "usage: mistakes lecture|closest|no-offset|epsilon=E|no-tmax|"
                    "light-shadows [step options]\n");
    return 2;
  }
  argv[1] = argv[0];
  const Step step = {
      .name = "mistakes",
      .summary = "Step 06's shading with another shadow test (docs/05-shadows.md).",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT |
                  SCENE_LIGHT_SHAPES,
      .pixel = pixel,
  };
  return app_run(argc - 1, argv + 1, &step);
}
