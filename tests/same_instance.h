/* Two instances alike, for the tests that compare two parses of one scene:
 * shape, material, light and the shape's data, compared by the union member
 * the shape uses (the rest of the union's bytes are unspecified after a
 * member's store; a case for each shape of SHAPE_REGISTRY, common/shapes.h). */
#ifndef RT_TEST_SAME_INSTANCE_H
#define RT_TEST_SAME_INSTANCE_H

#include <stdbool.h>
#include <string.h>

#include "scene.h"

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

#endif
