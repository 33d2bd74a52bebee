/* A view of the scene for one point's shadow rays toward an area light
 * (index/light_view.h). Each test is still the shape's own function; the
 * view only chooses which. */
#include "index/light_view.h"

#include <stddef.h>

#include "index/accel.h"

static const PackView *view_of(const Scene *scene)
{
  return (const PackView *)((const char *)scene->index - offsetof(PackView, index));
}

static bool view_any(const Scene *scene, const Ray *r, float tmax)
{
  const PackView *v = view_of(scene);
  for (int k = 0; k < v->n; k++)
    if (scene_instance_hit_t(&scene->instances[v->ids[k]], *r, tmax) < tmax)
      return true;
  return false;
}

/* The closest hit is the whole scene's: through its own index, or its loop. */
static const Instance *view_closest(const Scene *scene, const Ray *r, float *tmax)
{
  const PackView *v = view_of(scene);
  if (v->whole->index)
    return v->whole->index->closest(v->whole, r, tmax);
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

static void view_destroy(SceneIndex *index)
{
  (void)index; /* the caller's storage: nothing to free */
}

int light_view_make(const Scene *scene, const Hit *hit, const Quad *q, PackView *view)
{
  int n = accel_quad_occluders(scene, hit, q, view->ids, PACK_VIEW_MAX);
  if (n == 0) {
    view->scene = scene_view_unoccluded(scene);
  } else if (n > 0) {
    view->index = (SceneIndex){view_closest, view_any, view_destroy};
    view->whole = scene;
    view->n = n;
    view->scene = *scene;
    view->scene.index = &view->index;
  } else {
    view->scene = *scene;
  }
  return n;
}
