/* Step 08, area lights: parallelogram lights sampled as N point lights,
 * stratified, giving soft shadows. docs/08-area-lights.md. */
#include "app.h"
#include "shade.h"

static vec3s pixel(const Scene *scene, const Film *film, int i, int j, RenderCtx *ctx)
{
  vec2s s = film_sample(film, i, j);
  return shade_trace(scene, camera_ray(&scene->camera, s.x, s.y), ctx);
}

int main(int argc, char **argv)
{
  const Step step = {
      .name = "08-area-lights",
      .summary = "Step 08: area lights (soft shadows from stratified light samples).",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES |
                  SCENE_SAMPLES | SCENE_AREA_LIGHTS,
      .sampler = "jitter",
      .pixel = pixel,
  };
  return app_run(argc, argv, &step);
}
