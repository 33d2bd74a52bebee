/* Step 07, antialiasing: the pixel as the mean colour over its square (a box
 * filter), from samples of a selectable pattern or, adaptively, from its
 * corners, cut in four where they differ (antialias_pixel, common/antialias.c).
 * docs/07-antialiasing.md. */
#include "antialias.h"
#include "app/app.h"

int main(int argc, char **argv)
{
  const Step step = {
      .name = "07-antialiasing",
      .summary = "Step 07: antialiasing, several samples per pixel and adaptive sampling.\n"
                 "Defaults: the scene's samples, --adaptive 0.05 (corners and centre, cut in\n"
                 "four where they differ); with --adaptive 0, --sampler sobol (unbiased).",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT |
                  SCENE_LIGHT_SHAPES | SCENE_SAMPLES,
      .sampler = "sobol",
      .adaptive = 0.05f,
      .pixel = antialias_pixel,
  };
  return app_run(argc, argv, &step);
}
