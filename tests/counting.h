/* A query table that counts a scene's queries, for the tests that count
 * the rays the shading functions trace (tests/test_shadows.c,
 * tests/test_area_light.c): the render counts them the same way
 * (common/app/render.c). */
#ifndef RT_COUNTING_H
#define RT_COUNTING_H

#include "scene.h"
#include "scene_index.h"

/* A query table that counts the queries of a scene (then answers them as
 * that scene does): how many shadow rays the shading functions trace. */
typedef struct CountingTable {
  SceneIndex base; /* first member: the counted copy's index points here */
  const Scene *inner;
  int queries;
} CountingTable;

static inline const Instance *counting_closest(const Scene *s, const Ray *r, float *tmax)
{
  CountingTable *t = (CountingTable *)s->index;
  t->queries++;
  return scene_closest(t->inner, r, tmax);
}

static inline bool counting_any(const Scene *s, const Ray *r, float tmax)
{
  CountingTable *t = (CountingTable *)s->index;
  t->queries++;
  return scene_any(t->inner, r, tmax);
}

/* A copy of `s` whose queries `t` counts. */
static inline Scene counted(const Scene *s, CountingTable *t)
{
  *t = (CountingTable){.base = {.closest = counting_closest, .any = counting_any}, .inner = s};
  Scene c = *s;
  c.index = &t->base;
  return c;
}

#endif
