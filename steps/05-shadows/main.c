/* Step 05, shadows: Phong shading where a light counts only when nothing
 * lies between the point and the light. docs/05-shadows.md. */
#include "app/app.h"
#include "shade.h"

int main(int argc, char **argv)
{
  const Step step = {
      .name = "05-shadows",
      .summary = "Step 05: Phong shading with shadows (any-hit shadow rays).",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS,
      .pixel = shade_pixel,
  };
  return app_run(argc, argv, &step);
}
