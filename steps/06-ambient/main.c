/* Step 06, ambient light: Phong with shadows plus a constant ambient term,
 * and point lights the camera sees. docs/06-ambient.md. */
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
