/* Step 02, ray-object intersection: what a closest-hit query returns, seen
 * through a fixed camera. Left half: the normal n as colour 0.5 (n + 1).
 * Right half: the depth t as grey 1 - t / 20 (black from 20 units on). docs/02-intersection.md. */
#include "app/app.h"
#include "film.h"
#include "scene.h"

/* The fixed camera of this step: at (0, 1.5, 8), looking along -z, 40 degrees
 * vertical field of view. Step 03 replaces it with the scene's camera. */
static Ray fixed_camera_ray(const Film *film, vec2s s)
{
  float half_h = tanf(0.5f * glm_rad(40.0f));
  float half_w = half_h * (float)film->width / (float)film->height;
  vec3s d = vec_make((2.0f * s.x - 1.0f) * half_w, (2.0f * s.y - 1.0f) * half_h, -1.0f);
  Ray r = {.o = vec_make(0.0f, 1.5f, 8.0f), .d = glms_vec3_normalize(d)};
  return r;
}

static vec3s pixel(const Scene *scene, const Film *film, int i, int j)
{
  vec2s s = film_sample(film, i, j);
  Ray r = fixed_camera_ray(film, s);
  Hit hit;
  if (!scene_intersect(scene, r, INFINITY, &hit))
    return scene->background;
  if (s.x < 0.5f)
    return glms_vec3_scale(glms_vec3_adds(hit.n, 1.0f), 0.5f);
  float grey = fmaxf(0.0f, 1.0f - hit.t / 20.0f);
  return vec_make(grey, grey, grey);
}

int main(int argc, char **argv)
{
  const Step step = {
      STEP_MANIFEST, /* name, summary, features, sampler, adaptive: step.mk */
      .pixel = pixel,
  };
  return app_run(argc, argv, &step);
}
