/* Scene: instances, lights, materials and the ray queries (step 02 on).
 * docs/02-intersection.md, docs/05-shadows.md. */
#include "scene.h"
#include "scene_index.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"

void scene_init(Scene *scene)
{
  memset(scene, 0, sizeof *scene);
  scene->width = 800;
  scene->height = 600;
  scene->samples = 1;
  scene->light_samples = 1;
  scene->sampler = (Sampler){.kind = SAMPLER_CENTER, .seed = 1};
  camera_init(&scene->camera, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 0.0f, -1.0f),
              vec_make(0.0f, 1.0f, 0.0f), 45.0f, 1.0f, 800.0f / 600.0f);
}

void scene_free(Scene *scene)
{
  free(scene->materials);
  free(scene->lights);
  free(scene->instances);
  scene_init(scene);
}

/* Room for `more` elements after *count in a growing array (common/grow.h). */
static bool reserve(void **array, int count, int more, size_t size)
{
  if (grow_reserve(array, (size_t)count, (size_t)more, size))
    return true;
  fprintf(stderr, "scene: out of memory\n");
  return false;
}

/* Append one element of `size` bytes to a growing array. */
static bool push(void **array, int *count, size_t size, const void *elem)
{
  if (!reserve(array, *count, 1, size))
    return false;
  memcpy((char *)*array + size * (size_t)*count, elem, size);
  ++*count;
  return true;
}

bool scene_add_material(Scene *scene, const Material *m)
{
  return push((void **)&scene->materials, &scene->n_materials, sizeof *m, m);
}

bool scene_add_light(Scene *scene, const Light *light)
{
  return push((void **)&scene->lights, &scene->n_lights, sizeof *light, light);
}

bool scene_add_instance(Scene *scene, const Instance *inst)
{
  if (!reserve((void **)&scene->instances, scene->n_instances, 1, sizeof(Instance)))
    return false;
  scene->instances[scene->n_instances++] = *inst;
  if (inst->material >= 0)
    scene->n_shapes = scene->n_instances;
  return true;
}

int scene_find_material(const Scene *scene, const char *name)
{
  for (int k = 0; k < scene->n_materials; k++)
    if (strcmp(scene->materials[k].name, name) == 0)
      return k;
  return -1;
}

/* Keep the lights a step renders; note the kinds it drops. */
static void keep_lights(Scene *scene, unsigned features)
{
  int kept = 0;
  for (int k = 0; k < scene->n_lights; k++) {
    const Light *light = &scene->lights[k];
    bool area = light->type == LIGHT_AREA;
    if (!(features & SCENE_LIGHTS)) {
      scene->info.ignored |= area ? SCENE_AREA_LIGHTS : SCENE_LIGHTS;
    } else if (area && !(features & SCENE_AREA_LIGHTS)) {
      scene->info.ignored |= SCENE_AREA_LIGHTS;
    } else {
      scene->lights[kept++] = *light;
    }
  }
  scene->n_lights = kept;
}

/* Append the shapes the camera sees of the kept lights. */
static bool add_light_shapes(Scene *scene, unsigned features)
{
  for (int k = 0; k < scene->n_lights; k++) {
    const Light *light = &scene->lights[k];
    Instance inst = {.material = -1, .light = k};
    if (light->type == LIGHT_AREA) {
      inst.shape = SHAPE_QUAD;
      inst.quad = &light->quad;
    } else if (light->type == LIGHT_POINT && light->radius > 0.0f) {
      if (!(features & SCENE_LIGHT_SHAPES)) {
        scene->info.ignored |= SCENE_LIGHT_SHAPES;
        continue;
      }
      inst.shape = SHAPE_SPHERE;
      inst.sphere = (Sphere){.center = light->position, .radius = light->radius};
    } else {
      continue;
    }
    if (!reserve((void **)&scene->instances, scene->n_instances, 1, sizeof(Instance)))
      return false;
    scene->instances[scene->n_instances++] = inst;
  }
  return true;
}

/* info.ambient: whether some lit shape's m_amb l_amb is non-zero (no look at
 * the shapes when the ambient light is off, none after the first). */
static void analyze(Scene *scene)
{
  if (vec_is_zero(scene->ambient))
    return;
  for (int k = 0; k < scene->n_shapes; k++) {
    const Material *m = &scene->materials[scene->instances[k].material];
    if (!vec_is_zero(glms_vec3_mul(m->ambient, scene->ambient))) {
      scene->info.ambient = true;
      return;
    }
  }
}

bool scene_prepare(Scene *scene, unsigned features)
{
  memset(&scene->info, 0, sizeof scene->info);
  scene->info.shadows = (features & SCENE_SHADOWS) != 0;
  scene->n_instances = scene->n_shapes; /* in case of a second call */
  scene->index = NULL;                  /* built over the instances of a first call */
  if (!(features & SCENE_AMBIENT) && !vec_is_zero(scene->ambient)) {
    scene->info.ignored |= SCENE_AMBIENT;
    scene->ambient = glms_vec3_zero();
  }
  if (!(features & SCENE_SAMPLES) && scene->samples > 1) {
    scene->info.ignored |= SCENE_SAMPLES;
    scene->samples = 1;
  }
  keep_lights(scene, features);
  if (!(features & SCENE_AREA_LIGHTS) && scene->light_samples > 1) {
    scene->info.ignored |= SCENE_AREA_LIGHTS;
    scene->light_samples = 1;
  }
  if (!add_light_shapes(scene, features))
    return false;
  analyze(scene);
  Camera *cam = &scene->camera;
  camera_init(cam, cam->eye, cam->center, cam->up, cam->fov_y_deg, cam->focal,
              (float)scene->width / (float)scene->height);
  return true;
}

/* The dispatch to each shape's functions: a switch with a case per line of
 * SHAPE_REGISTRY (common/shapes.h), e.g. for the disc
 *   case SHAPE_DISC: return disc_hit_t(inst->disc, r, tmax);
 * A switch, not a table of function pointers: the compiler inlines each
 * shape's test into the queries' loops. */
float scene_instance_hit_t(const Instance *inst, Ray r, float tmax)
{
#define HIT_T_(NAME, name, Type, STORE, DOC)                                           \
  case SHAPE_##NAME: return name##_hit_t(SHAPE_OF(inst, name, STORE), r, tmax);
  switch (inst->shape) {
    SHAPE_REGISTRY(HIT_T_)
  case SHAPE_COUNT: break;
  }
#undef HIT_T_
  return INFINITY;
}

static void instance_hit_fill(const Instance *inst, Ray r, float t, Hit *hit)
{
#define HIT_FILL_(NAME, name, Type, STORE, DOC)                                        \
  case SHAPE_##NAME: name##_hit_fill(SHAPE_OF(inst, name, STORE), r, t, hit); break;
  switch (inst->shape) {
    SHAPE_REGISTRY(HIT_FILL_)
  case SHAPE_COUNT: break;
  }
#undef HIT_FILL_
  hit->material = inst->material;
  hit->light = inst->light;
  hit->inst = inst;
}

Box scene_instance_bounds(const Instance *inst)
{
#define BOUNDS_(NAME, name, Type, STORE, DOC)                                          \
  case SHAPE_##NAME: return name##_bounds(SHAPE_OF(inst, name, STORE));
  switch (inst->shape) {
    SHAPE_REGISTRY(BOUNDS_)
  case SHAPE_COUNT: break;
  }
#undef BOUNDS_
  return (Box){vec_make(-INFINITY, -INFINITY, -INFINITY), vec_make(INFINITY, INFINITY, INFINITY)};
}

const char *scene_shape_name(ShapeType shape)
{
#define NAME_(NAME, name, Type, STORE, DOC) [SHAPE_##NAME] = #name,
  static const char *const names[SHAPE_COUNT] = {SHAPE_REGISTRY(NAME_)};
#undef NAME_
  return (unsigned)shape < SHAPE_COUNT ? names[shape] : "?";
}

const Instance *scene_closest(const Scene *scene, const Ray *r, float *tmax)
{
  if (scene->index)
    return scene->index->closest(scene, r, tmax);
  const Instance *best = NULL;
  for (int k = 0; k < scene->n_instances; k++) {
    float t = scene_instance_hit_t(&scene->instances[k], *r, *tmax);
    if (t < *tmax) {
      *tmax = t;
      best = &scene->instances[k];
    }
  }
  return best;
}

bool scene_any(const Scene *scene, const Ray *r, float tmax)
{
  if (scene->index)
    return scene->index->any(scene, r, tmax);
  for (int k = 0; k < scene->n_shapes; k++)
    if (scene_instance_hit_t(&scene->instances[k], *r, tmax) < tmax)
      return true;
  return false;
}

bool scene_intersect(const Scene *scene, Ray r, float tmax, Hit *hit)
{
  const Instance *best = scene_closest(scene, &r, &tmax);
  if (!best)
    return false;
  instance_hit_fill(best, r, tmax, hit);
  return true;
}

bool scene_occluded(const Scene *scene, Ray r, float tmax)
{
  return scene_any(scene, &r, tmax);
}
