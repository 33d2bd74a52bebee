/* The image test of every step (compiled once per step with STEP_NAME and
 * BUILD_DIR): render the step's default scene at the reference size and
 * compare it with images/STEP_NAME.png. docs/testing.md.
 *
 * Tolerance. The binary writes a .pfm (the film's exact floats); each float is
 * clamped to [0, 1] (what the PNG export does) and compared with the
 * reference byte / 255. A render identical to the reference's differs by at
 * most 0.5/255 (the byte's rounding). Another compiler, -march or libm may
 * move a value across a rounding boundary: 1.5/255 then still passes. A
 * channel may exceed 1.5/255 in at most 0.1% of channels (a silhouette pixel
 * whose ray grazes a sphere can flip between two objects), but never 16/255:
 * a wrong formula moves whole regions by far more than that.
 * A noisy step (07, 08) may loosen this with images/STEP_NAME.tol: two or
 * three numbers, "tol fraction [max]", tol and max in 1/255 units (the
 * defaults are "1.5 0.001 16"). */
#include <criterion/criterion.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "app/image.h"

typedef struct Tolerance {
  double tol, fraction, max; /* tol and max in 1/255 units */
} Tolerance;

/* The step's tolerance: the defaults above, or images/STEP_NAME.tol. */
static Tolerance tolerance(void)
{
  Tolerance t = {1.5, 0.001, 16.0};
  FILE *f = fopen("images/" STEP_NAME ".tol", "r");
  if (!f)
    return t;
  double tol, fraction, max;
  int n = fscanf(f, "%lf %lf %lf", &tol, &fraction, &max);
  fclose(f);
  cr_assert(n >= 2 && tol > 0.0 && fraction >= 0.0 && fraction < 1.0,
            "images/" STEP_NAME ".tol: expected 'tol fraction [max]' (tol in 1/255 "
            "units, fraction in [0, 1))");
  t.tol = tol;
  t.fraction = fraction;
  t.max = n >= 3 ? max : fmax(16.0, tol);
  return t;
}

Test(image, step_matches_its_reference_image, .timeout = 300)
{
  const char *ref_path = "images/" STEP_NAME ".png";
  const char *out_path = BUILD_DIR "/test-out/" STEP_NAME ".pfm";
  const char *diff_path = BUILD_DIR "/diff/" STEP_NAME ".png";
  int rw, rh, w, h;
  float *ref, *out;
  cr_assert(image_load(ref_path, &rw, &rh, &ref),
            "no reference image %s (make images writes it)", ref_path);
  mkdir(BUILD_DIR "/test-out", 0755);
  remove(out_path);
  char cmd[512];
  snprintf(cmd, sizeof cmd, "%s/bin/%s --width %d --height %d --threads 2 --quiet -o %s",
           BUILD_DIR, STEP_NAME, rw, rh, out_path);
  int status = system(cmd);
  cr_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0, "'%s' failed", cmd);
  cr_assert(image_load(out_path, &w, &h, &out), "cannot read the render %s", out_path);
  cr_assert(w == rw && h == rh, "render is %dx%d, reference %dx%d", w, h, rw, rh);

  /* The PNG holds round(255 clamp(c, 0, 1)): compare with the clamped floats. */
  size_t n = (size_t)w * h * 3;
  for (size_t k = 0; k < n; k++)
    out[k] = out[k] != out[k] ? 1e9f : fminf(fmaxf(out[k], 0.0f), 1.0f);
  Tolerance t = tolerance();
  ImageDiff d = image_compare(w, h, out, ref, (float)(t.tol / 255.0));
  double over = (double)d.over / (double)n;
  bool pass = over <= t.fraction && d.max_abs <= t.max / 255.0;
  if (!pass) {
    mkdir(BUILD_DIR "/diff", 0755);
    image_save_diff(diff_path, w, h, out, ref, (float)(t.tol / 255.0), 8.0f);
  } else {
    remove(diff_path); /* no stale picture from an earlier failure */
  }
  cr_log_info("%s: %dx%d, %ld of %zu channels over %.2f/255 (%.4f%%, allowed %.4f%%), "
              "max %.2f/255 (allowed %.2f/255), rmse %.3f/255", STEP_NAME, w, h,
              d.over, n, t.tol, 100.0 * over, 100.0 * t.fraction,
              255.0 * d.max_abs, t.max, 255.0 * d.rmse);
  cr_expect(pass, "%s differs from %s: %ld channels over %.2f/255 (%.4f%%, allowed "
            "%.4f%%), max %.2f/255 (allowed %.2f/255); diff picture: %s (red: over)",
            out_path, ref_path, d.over, t.tol, 100.0 * over, 100.0 * t.fraction,
            255.0 * d.max_abs, t.max, diff_path);
  free(ref);
  free(out);
}
