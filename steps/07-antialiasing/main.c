/* Step 07, antialiasing: the pixel as the mean colour over its square (a box
 * filter), from samples of a selectable pattern or, adaptively, from its
 * corners, cut in four where they differ (antialias_pixel, common/antialias.c).
 * docs/07-antialiasing.md. */
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
