/* Step 04, Phong: the scene lit by point and directional lights with the
 * Phong model, no shadows yet. docs/04-phong.md. */
#include "app/app.h"
#include "shade.h"

int main(int argc, char **argv)
{
  const Step step = {
      STEP_MANIFEST, /* name, summary, features, sampler, adaptive: step.mk */
      .pixel = shade_pixel,
  };
  return app_run(argc, argv, &step);
}
