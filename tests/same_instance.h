/* Two instances alike, for the tests that compare two parses of one scene:
 * shape, material, light and the shape's data, compared by the union member
 * the shape uses (the rest of the union's bytes are unspecified after a
 * member's store; a case for each shape of SHAPE_REGISTRY, common/shapes.h),
 * and two scenes alike, value by value. */
#ifndef RT_TEST_SAME_INSTANCE_H
#define RT_TEST_SAME_INSTANCE_H

#include <stdbool.h>
#include <string.h>

#include "scene.h"
#include "shapes.h"

static inline bool same_instance(const Instance *a, const Instance *b)
{
  if (a->shape != b->shape || a->material != b->material || a->light != b->light)
    return false;
#define SAME_(NAME, name, Type, STORE, DOC)                                            \
  case SHAPE_##NAME:                                                                   \
    return memcmp(SHAPE_OF(a, name, STORE), SHAPE_OF(b, name, STORE), sizeof(Type)) == 0;
  switch (a->shape) {
    SHAPE_REGISTRY(SAME_)
  case SHAPE_COUNT: break;
  }
#undef SAME_
  return false;
}

static inline bool same_instances(const Instance *a, const Instance *b, int n)
{
  for (int k = 0; k < n; k++)
    if (!same_instance(&a[k], &b[k]))
      return false;
  return true;
}

/* A scene's contents as bytes, for comparing two parses. */
static inline bool same_scene(const Scene *a, const Scene *b)
{
  return a->width == b->width && a->height == b->height && a->samples == b->samples &&
         a->light_samples == b->light_samples &&
         memcmp(&a->camera, &b->camera, sizeof a->camera) == 0 &&
         memcmp(&a->ambient, &b->ambient, sizeof a->ambient) == 0 &&
         memcmp(&a->background, &b->background, sizeof a->background) == 0 &&
         a->n_materials == b->n_materials && a->n_lights == b->n_lights &&
         a->n_instances == b->n_instances && a->n_shapes == b->n_shapes &&
         (a->n_materials == 0 || memcmp(a->materials, b->materials,
                                        sizeof *a->materials * (size_t)a->n_materials) == 0) &&
         (a->n_lights == 0 || memcmp(a->lights, b->lights,
                                     sizeof *a->lights * (size_t)a->n_lights) == 0) &&
         same_instances(a->instances, b->instances, a->n_instances);
}

#endif
