/* Step 06, ambient light: Phong with shadows plus a constant ambient term,
 * and point lights the camera sees. docs/06-ambient.md. */
#include "app/app.h"
#include "shade.h"

static vec3s pixel(const Scene *scene, const Film *film, int i, int j, RenderCtx *ctx)
{
  vec2s s = film_sample(film, i, j);
  return shade_trace(scene, camera_ray(&scene->camera, s.x, s.y), ctx);
}

int main(int argc, char **argv)
{
  const Step step = {
      STEP_MANIFEST, /* name, summary, features, sampler, adaptive: step.mk */
      .pixel = pixel,
  };
  return app_run(argc, argv, &step);
}
