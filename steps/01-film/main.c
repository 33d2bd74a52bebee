/* Step 01, the film: a test picture of four coloured quadrants, red at the
 * bottom left, green top left, blue bottom right, white top right. It checks
 * the film's row order (j from the bottom) and the export. docs/01-film.md. */
#include "app/app.h"
#include "film.h"

static vec3s pixel(const Scene *scene, const Film *film, int i, int j)
{
  (void)scene;
  /* BEGIN SOLUTION step 01 */
  bool left = i < film->width / 2, bottom = j < film->height / 2;
  if (left)
    return bottom ? vec_make(1.0f, 0.0f, 0.0f) : vec_make(0.0f, 1.0f, 0.0f);
  return bottom ? vec_make(0.0f, 0.0f, 1.0f) : vec_make(1.0f, 1.0f, 1.0f);
  /* STUB: return vec_make(0.0f, 0.0f, 0.0f); */
  /* END SOLUTION */
}

int main(int argc, char **argv)
{
  const Step step = {
      STEP_MANIFEST, /* name, summary, features, sampler, adaptive: step.mk */
      .pixel = pixel,
  };
  return app_run(argc, argv, &step);
}
