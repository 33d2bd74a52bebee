/* Step 08, area lights: step 07's antialiased pixels, shaded with
 * parallelogram lights sampled as N point lights (soft shadows; shade_area,
 * common/shade.c). docs/08-area-lights.md. */
#include "antialias.h"
#include "app/app.h"

int main(int argc, char **argv)
{
  const Step step = {
      .name = "08-area-lights",
      .summary = "Step 08: area lights, soft shadows from stratified light samples.\n"
                 "Defaults: the scene's samples and light_samples, --sampler sobol, --adaptive 0\n"
                 "(unbiased: every pixel takes all its samples).",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT |
                  SCENE_LIGHT_SHAPES | SCENE_SAMPLES | SCENE_AREA_LIGHTS,
      .sampler = "sobol",
      .adaptive = 0.0f,
      .pixel = antialias_pixel,
  };
  return app_run(argc, argv, &step);
}
