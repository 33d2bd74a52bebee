/* Step 05, shadows: Phong shading where a light counts only when nothing
 * lies between the point and the light. docs/05-shadows.md. */
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
