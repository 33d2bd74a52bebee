/* Acceleration structure (docs/performance.md). Until a scene is large enough
 * to need one, the scene queries loop over the instances. */
#include "accel.h"

bool accel_build(Scene *scene)
{
  scene->accel = NULL;
  return true;
}

void accel_free(Scene *scene)
{
  scene->accel = NULL;
}

const Instance *accel_closest(const Scene *scene, Ray r, float *tmax)
{
  (void)scene;
  (void)r;
  (void)tmax;
  return NULL;
}

bool accel_any(const Scene *scene, Ray r, float tmax)
{
  (void)scene;
  (void)r;
  (void)tmax;
  return false;
}
