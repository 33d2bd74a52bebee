/* Step 06, ambient light: Phong with shadows plus a constant ambient term,
 * and point lights the camera sees. docs/06-ambient.md. */
#include "app/app.h"
#include "shade.h"

int main(int argc, char **argv)
{
  const Step step = {
      .name = "06-ambient",
      .summary = "Step 06: ambient light, and point lights the camera sees.",
      .features = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT |
                  SCENE_LIGHT_SHAPES,
      .pixel = shade_pixel,
  };
  return app_run(argc, argv, &step);
}
