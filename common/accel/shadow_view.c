/* A view of the scene for one point's shadow rays toward an area light: its
 * any-hit queries test only the lit shapes that may stand in the way (step 08,
 * docs/performance.md, "Work skipped exactly"). Each test is still the
 * shape's own function; the view only chooses which. */
#include "accel/accel.h"

static bool view_any(const Scene *scene, const Ray *r, float tmax)
{
  const AccelShadowView *v = (const AccelShadowView *)scene->index;
  for (int k = 0; k < v->n; k++)
    if (scene_instance_hit_t(&scene->instances[v->ids[k]], *r, tmax) < tmax)
      return true;
  return false;
}

/* The closest hit is the whole scene's: through its own index, or its loop. */
static const Instance *view_closest(const Scene *scene, const Ray *r, float *tmax)
{
  const AccelShadowView *v = (const AccelShadowView *)scene->index;
  if (v->scene->index)
    return v->scene->index->closest(v->scene, r, tmax);
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

int accel_shadow_view(const Scene *scene, const Hit *hit, const Quad *q,
                      AccelShadowView *storage, Scene *view)
{
  int n = accel_quad_occluders(scene, hit, q, storage->ids, ACCEL_VIEW_MAX);
  if (n == 0) {
    *view = scene_view_unoccluded(scene);
  } else if (n > 0) {
    storage->index = (SceneIndex){view_closest, view_any, view_destroy};
    storage->scene = scene;
    storage->n = n;
    *view = *scene;
    view->index = &storage->index;
  } else {
    *view = *scene;
  }
  return n;
}
