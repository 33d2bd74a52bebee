/* Step 08, area lights: step 07's antialiased pixels, shaded with
 * parallelogram lights sampled as N point lights (soft shadows; shade_area,
 * common/area_light.c). docs/08-area-lights.md. */
#include "antialias.h"
#include "app/app.h"

int main(int argc, char **argv)
{
  const Step step = {
      STEP_MANIFEST, /* name, summary, features, sampler, adaptive: step.mk */
      .pixel = antialias_pixel,
  };
  return app_run(argc, argv, &step);
}
