/* Step 03, the pinhole camera: the scene seen through the lookAt camera of
 * the scene file, each object in its flat diffuse colour. docs/03-camera.md. */
#include "app/app.h"
#include "film.h"
#include "scene.h"

static vec3s pixel(const Scene *scene, const Film *film, int i, int j)
{
  vec2s s = film_sample(film, i, j);
  Ray r = camera_ray(&scene->camera, s.x, s.y);
  Hit hit;
  if (!scene_intersect(scene, r, INFINITY, &hit))
    return scene->background;
  return scene->materials[hit.material].diffuse;
}

int main(int argc, char **argv)
{
  const Step step = {
      STEP_MANIFEST, /* name, summary, features, sampler, adaptive: step.mk */
      .pixel = pixel,
  };
  return app_run(argc, argv, &step);
}
