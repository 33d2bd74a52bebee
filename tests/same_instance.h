/* Two instances alike, for the tests that compare two parses of one scene:
 * shape, material, light and the shape's data, compared by the union member
 * the shape uses (the rest of the union's bytes are unspecified after a
 * member's store; the switch has a case for each ShapeType: -Wswitch). */
#ifndef RT_TEST_SAME_INSTANCE_H
#define RT_TEST_SAME_INSTANCE_H

#include <stdbool.h>
#include <string.h>

#include "scene.h"

static inline bool same_instance(const Instance *a, const Instance *b)
{
  if (a->shape != b->shape || a->material != b->material || a->light != b->light)
    return false;
  switch (a->shape) {
  case SHAPE_SPHERE: return memcmp(&a->sphere, &b->sphere, sizeof a->sphere) == 0;
  case SHAPE_PLANE:  return memcmp(&a->plane, &b->plane, sizeof a->plane) == 0;
  case SHAPE_QUAD:   return memcmp(a->quad, b->quad, sizeof *a->quad) == 0;
  case SHAPE_DISC:   return memcmp(&a->disc, &b->disc, sizeof a->disc) == 0;
  }
  return false;
}

#endif
