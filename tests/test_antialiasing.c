/* Tests of step 07's pixel integrator, run through the step's binary: a pixel
 * cut by one straight edge converges to the exact covered fraction (bounds
 * worked out from the patterns' strata), the random estimate is unbiased over
 * seeds, adaptive sampling stops where samples agree, and the bytes do not
 * depend on the thread count. docs/07-antialiasing.md. */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "app/image.h"

#define OUT_DIR BUILD_DIR "/test-out"

/* One 1 x 1 pixel seen through a 90 degree camera at the origin looking down
 * -z: the image plane z = -1 spans X, Y in [-1, 1], X = 2 nx - 1, Y = 2 ny - 1.
 * The plane through (0.4, -0.35, 0.19) with that normal n is hit exactly by
 * the rays with d.n > 0 (t = |n|^2 / d.n > 0), the half of the image where
 * 0.4 X - 0.35 Y - 0.19 > 0, i.e. 0.8 nx - 0.7 ny - 0.24 > 0: the triangle
 * (0.3, 0), (1, 0), (1, 0.8) of the pixel, area 0.7 * 0.8 / 2 = 0.28. It is
 * white (ambient 1 times ambient colour 1), the rest black. */
static const char EDGE_SCENE[] =
    "film 1 1\n"
    "camera eye 0 0 0 center 0 0 -1 up 0 1 0 fov 90\n"
    "ambient 1 1 1\n"
    "material white ambient 1 1 1\n"
    "plane point 0.4 -0.35 0.19 normal 0.4 -0.35 0.19 material white\n";
static const double EDGE_FRACTION = 0.28;

/* Render `scene` (text, or NULL for the step's default) with `args` into a
 * .pfm named after `tag`; returns the pixels (caller frees) and the summary
 * line in `summary` when asked. */
static float *render(const char *tag, const char *scene, const char *args, int *w, int *h,
                     char *summary, size_t summary_len)
{
  char scene_path[256], out_path[256], cmd[1024];
  mkdir(OUT_DIR, 0755);
  snprintf(out_path, sizeof out_path, OUT_DIR "/aa-%s.pfm", tag);
  snprintf(scene_path, sizeof scene_path, OUT_DIR "/aa-%s.scene", tag);
  if (scene) {
    FILE *f = fopen(scene_path, "w");
    cr_assert(f && fputs(scene, f) >= 0 && fclose(f) == 0, "cannot write %s", scene_path);
  }
  remove(out_path);
  snprintf(cmd, sizeof cmd, BUILD_DIR "/bin/" STEP_NAME " %s%s %s -o %s", scene ? "--scene " : "",
           scene ? scene_path : "", args, out_path);
  FILE *p = popen(cmd, "r");
  cr_assert(p, "cannot run %s", cmd);
  char line[512] = "";
  while (fgets(line, sizeof line, p))
    if (summary)
      snprintf(summary, summary_len, "%s", line);
  cr_assert(pclose(p) == 0, "'%s' failed", cmd);
  float *rgb;
  cr_assert(image_load(out_path, w, h, &rgb), "cannot read %s", out_path);
  return rgb;
}

/* The single pixel's red value of the edge scene. */
static double edge_pixel(const char *tag, const char *args)
{
  int w, h;
  float *rgb = render(tag, EDGE_SCENE, args, &w, &h, NULL, 0);
  cr_assert(w == 1 && h == 1);
  double v = rgb[0];
  free(rgb);
  return v;
}

Test(antialiasing, one_centre_sample_sees_all_or_nothing)
{
  /* The centre (0.5, 0.5): 0.4 - 0.35 - 0.24 < 0, outside the triangle. */
  double v = edge_pixel("centre", "--sampler center --samples 1 --quiet");
  cr_expect(v == 0.0, "pixel %g, expected 0 (the centre misses the triangle)", v);
}

/* A straight line crosses at most 2k - 1 cells of a k x k grid (it enters a
 * new cell only across one of the k - 1 inner vertical or horizontal lines).
 * Any cell it does not cross is wholly in or out, so its one sample counts it
 * exactly; a crossed cell errs by at most its area 1/k^2. Hence
 * |estimate - 0.28| <= (2k - 1) / k^2 for grid and jitter with k^2 samples,
 * and for Sobol with 4^m samples (one point in every 2^m x 2^m square box). */
Test(antialiasing, stratified_patterns_converge_to_the_covered_fraction)
{
  const char *kinds[] = {"grid", "jitter", "sobol"};
  for (int s = 0; s < 3; s++)
    for (int k = 2; k <= 64; k *= 2) {
      char args[128], tag[64];
      snprintf(args, sizeof args, "--sampler %s --samples %d --adaptive 0 --quiet", kinds[s],
               k * k);
      snprintf(tag, sizeof tag, "conv-%s-%d", kinds[s], k);
      double v = edge_pixel(tag, args), bound = (2.0 * k - 1.0) / (k * k);
      cr_expect(fabs(v - EDGE_FRACTION) <= bound, "%s, %d samples: %.6f, exact %.2f, bound %.5f",
                kinds[s], k * k, v, EDGE_FRACTION, bound);
    }
}

/* Random samples are Bernoulli(0.28): over 24 seeds of 64 samples each, the
 * mean is within 4 standard errors sqrt(0.28 * 0.72 / (64 * 24)) = 0.0115 of
 * the exact fraction, and the estimates do vary. */
Test(antialiasing, random_sampling_is_unbiased_over_seeds)
{
  double sum = 0.0, sum2 = 0.0;
  const int seeds = 24, n = 64;
  for (int seed = 1; seed <= seeds; seed++) {
    char args[128], tag[64];
    snprintf(args, sizeof args, "--sampler random --samples %d --adaptive 0 --seed %d --quiet", n,
             seed);
    snprintf(tag, sizeof tag, "random-%d", seed);
    double v = edge_pixel(tag, args);
    sum += v;
    sum2 += v * v;
  }
  double mean = sum / seeds, var = (sum2 - sum * sum / seeds) / (seeds - 1);
  double se = sqrt(EDGE_FRACTION * (1.0 - EDGE_FRACTION) / (n * seeds));
  cr_expect(fabs(mean - EDGE_FRACTION) <= 4.0 * se, "mean %.5f, exact %.2f, 4 se = %.5f",
            mean, EDGE_FRACTION, 4.0 * se);
  cr_expect(var > 0.0, "the estimate is the same for every seed");
}

/* Adaptive, Sobol, 1024 samples: the first quarter, 256 points, has one
 * point in each of the 16 x 16 square boxes; some boxes lie wholly inside
 * the triangle (the box [0.75, 0.8125) x [0, 0.0625), say: its corners all
 * have 0.8 nx - 0.7 ny - 0.24 > 0) and some wholly outside ([0, 0.0625)^2),
 * so the samples disagree and all 1024 points are traced: one in each
 * 32 x 32 box, hence the bound (2 * 32 - 1) / 1024 above. */
Test(antialiasing, adaptive_spends_the_budget_on_an_edge_pixel)
{
  double v = edge_pixel("adaptive", "--sampler sobol --samples 1024 --adaptive 0.01 --quiet");
  double bound = 63.0 / 1024.0;
  cr_expect(fabs(v - EDGE_FRACTION) <= bound, "%.6f, exact %.2f, bound %.5f", v, EDGE_FRACTION,
            bound);
}

/* The summary's "N Mrays" of a render. */
static double mrays(const char *summary)
{
  const char *at = strstr(summary, " spp, ");
  cr_assert(at, "no summary line: '%s'", summary);
  return atof(at + 6);
}

/* A 400 x 100 film of background only: every pixel's samples agree, so
 * adaptive sampling traces the first quarter of the 64 samples,
 * 400 * 100 * 16 = 0.64 Mrays; without it (threshold 0) all 64: 2.56 Mrays. */
Test(antialiasing, adaptive_stops_after_four_samples_where_they_agree)
{
  static const char empty[] = "film 400 100\nbackground 0.2 0.3 0.4\n";
  char summary[512];
  int w, h;
  free(render("agree-on", empty, "--samples 64 --adaptive 0.01", &w, &h, summary,
              sizeof summary));
  cr_expect(fabs(mrays(summary) - 0.64) < 0.001, "adaptive: %s", summary);
  free(render("agree-off", empty, "--samples 64 --adaptive 0", &w, &h, summary,
              sizeof summary));
  cr_expect(fabs(mrays(summary) - 2.56) < 0.001, "not adaptive: %s", summary);
}

static bool same_floats(const char *a_args, const char *b_args, const char *tag)
{
  int wa, ha, wb, hb;
  char ta[64], tb[64];
  snprintf(ta, sizeof ta, "%s-a", tag);
  snprintf(tb, sizeof tb, "%s-b", tag);
  float *a = render(ta, NULL, a_args, &wa, &ha, NULL, 0);
  float *b = render(tb, NULL, b_args, &wb, &hb, NULL, 0);
  bool same = wa == wb && ha == hb && !memcmp(a, b, sizeof(float) * 3 * (size_t)wa * ha);
  free(a);
  free(b);
  return same;
}

Test(antialiasing, thread_count_does_not_change_the_floats, .timeout = 120)
{
  const char *kinds[] = {"random", "jitter", "sobol"};
  for (int s = 0; s < 3; s++) {
    char a[160], b[160], tag[32];
    const char *common = "--width 96 --height 72 --samples 8 --adaptive 0.05 --quiet";
    snprintf(a, sizeof a, "%s --sampler %s --threads 1", common, kinds[s]);
    snprintf(b, sizeof b, "%s --sampler %s --threads 3", common, kinds[s]);
    snprintf(tag, sizeof tag, "threads-%s", kinds[s]);
    cr_expect(same_floats(a, b, tag), "%s: --threads 1 and 3 differ", kinds[s]);
  }
}

Test(antialiasing, the_seed_changes_the_noise_and_only_the_seed)
{
  const char *base = "--width 64 --height 48 --samples 4 --sampler jitter --quiet";
  char a[160], b[160];
  snprintf(a, sizeof a, "%s --seed 7", base);
  snprintf(b, sizeof b, "%s --seed 8", base);
  cr_expect(same_floats(a, a, "seed-same"), "seed 7 twice differs");
  cr_expect(!same_floats(a, b, "seed-other"), "seeds 7 and 8 give the same picture");
}
