/* Tests of step 07's pixel integrator, run through the step's binary: a pixel
 * cut by one straight edge converges to the exact covered fraction (bounds
 * worked out from the patterns' strata and from the adaptive squares), the
 * random estimate is unbiased over seeds, every pixel takes its own sample
 * positions, adaptive sampling costs about two samples per pixel where the
 * picture is flat, and the floats and the ray count do not depend on the
 * thread count. docs/07-antialiasing.md. */
#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "app/image.h"

#define OUT_DIR BUILD_DIR "/test-out"
#define DOC_BOX "docs/07-antialiasing.md, \"The box filter\""
#define DOC_ADAPTIVE "docs/07-antialiasing.md, \"Adaptive sampling\""
#define DOC_KEYS "docs/07-antialiasing.md, \"Randomness\""

/* One 1 x 1 pixel seen through a 90 degree camera at the origin looking down
 * -z: the image plane z = -1 spans X, Y in [-1, 1], X = 2 nx - 1, Y = 2 ny - 1.
 * The plane through (0.4, -0.35, 0.19) with that normal n is hit exactly by
 * the rays with d.n > 0 (t = |n|^2 / d.n > 0), the half of the image where
 * 0.4 X - 0.35 Y - 0.19 > 0, i.e. 0.8 nx - 0.7 ny - 0.24 > 0: the triangle
 * (0.3, 0), (1, 0), (1, 0.8) of the pixel, area 0.7 * 0.8 / 2 = 0.28. It is
 * white (ambient 1 times ambient colour 1), the rest black. */
#define ONE_PIXEL                                                                \
  "film 1 1\n"                                                                   \
  "camera eye 0 0 0 center 0 0 -1 up 0 1 0 fov 90\n"                            \
  "ambient 1 1 1\n"                                                              \
  "material white ambient 1 1 1\n"
static const char EDGE_SCENE[] =
    ONE_PIXEL "plane point 0.4 -0.35 0.19 normal 0.4 -0.35 0.19 material white\n";
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
  if (summary)
    summary[0] = 0;
  char line[512] = "";
  while (fgets(line, sizeof line, p))
    if (summary)
      snprintf(summary, summary_len, "%s", line);
  cr_assert(pclose(p) == 0, "'%s' failed", cmd);
  float *rgb;
  cr_assert(image_load(out_path, w, h, &rgb), "cannot read %s", out_path);
  return rgb;
}

/* The single pixel's red value of `scene` (a 1 x 1 film). */
static double one_pixel(const char *tag, const char *scene, const char *args)
{
  int w, h;
  float *rgb = render(tag, scene, args, &w, &h, NULL, 0);
  cr_assert(w == 1 && h == 1);
  double v = rgb[0];
  free(rgb);
  return v;
}

Test(antialiasing, one_centre_sample_sees_all_or_nothing)
{
  /* The centre (0.5, 0.5): 0.4 - 0.35 - 0.24 < 0, outside the triangle. */
  Check c = CHECK("pixel (--adaptive 0)", DOC_BOX);
  CHECK_NEAR(&c, 0.0, one_pixel("centre", EDGE_SCENE, "--sampler center --samples 1 "
             "--adaptive 0 --quiet"), 0.0, "a pixel whose centre misses the white triangle, "
             "one sample at the centre: red");
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
  Check c = CHECK("pixel (--adaptive 0)", DOC_BOX);
  for (int s = 0; s < 3; s++)
    for (int k = 2; k <= 64; k *= 2) {
      char args[128], tag[64];
      snprintf(args, sizeof args, "--sampler %s --samples %d --adaptive 0 --quiet", kinds[s],
               k * k);
      snprintf(tag, sizeof tag, "conv-%s-%d", kinds[s], k);
      CHECK_NEAR(&c, EDGE_FRACTION, one_pixel(tag, EDGE_SCENE, args), (2.0 * k - 1.0) / (k * k),
                 "a pixel 28%% covered by a white triangle, %s, %d samples: red (the covered "
                 "fraction)", kinds[s], k * k);
    }
  CHECK_DONE(&c);
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
    double v = one_pixel(tag, EDGE_SCENE, args);
    sum += v;
    sum2 += v * v;
  }
  double mean = sum / seeds, var = (sum2 - sum * sum / seeds) / (seeds - 1);
  double se = sqrt(EDGE_FRACTION * (1.0 - EDGE_FRACTION) / (n * seeds));
  Check c = CHECK("pixel (--adaptive 0)", DOC_BOX);
  CHECK_NEAR(&c, EDGE_FRACTION, mean, 4.0 * se, "a pixel 28%% covered, random, 64 samples: "
             "mean red over 24 seeds (4 standard errors)");
  CHECK_THAT(&c, var > 0.0, "random, 64 samples: the same red for 24 seeds (%.6f): the "
             "samples must follow --seed", mean);
}

/* A row of 64 pixels (fov 90, so the image plane spans X in [-64, 64] and
 * Y in [-1, 1]); the plane through n = (0.01, -0.64, 0) with normal n is hit
 * where X - 64 Y > 0, i.e. below the line ny = nx of the film: pixel i is
 * white where its sample (u, v) has v < (i + u) / 64. With the same (u, v) in
 * every pixel, the row is black up to some pixel and white after it; with
 * each pixel's own random point, some white pixel comes before a black one. */
static const char ROW_SCENE[] =
    "film 64 1\n"
    "camera eye 0 0 0 center 0 0 -1 up 0 1 0 fov 90\n"
    "ambient 1 1 1\n"
    "material white ambient 1 1 1\n"
    "plane point 0.01 -0.64 0 normal 0.01 -0.64 0 material white\n";

Test(antialiasing, every_pixel_takes_its_own_sample_positions)
{
  const char *kinds[] = {"random", "jitter", "sobol"};
  Check c = CHECK("pixel_sampled (--adaptive 0): sampler_pattern keyed by the pixel", DOC_KEYS);
  for (int s = 0; s < 3; s++)
    for (int seed = 1; seed <= 3; seed++) {
      char args[128], tag[64];
      snprintf(args, sizeof args, "--sampler %s --samples 1 --adaptive 0 --seed %d --quiet",
               kinds[s], seed);
      snprintf(tag, sizeof tag, "row-%s-%d", kinds[s], seed);
      int w, h;
      float *rgb = render(tag, ROW_SCENE, args, &w, &h, NULL, 0);
      cr_assert(w == 64 && h == 1);
      int inversions = 0, white = 0;
      for (int i = 0; i < w; i++) {
        white += rgb[3 * i] > 0.5f;
        inversions += rgb[3 * i] < 0.5f && white > 0;
      }
      free(rgb);
      CHECK_THAT(&c, inversions > 0, "%s, 1 sample, seed %d: a row cut by a slanted edge came "
                 "out as one clean step (%d white pixels, all after the black ones): every "
                 "pixel sampled the same place", kinds[s], seed, white);
    }
  CHECK_DONE(&c);
}

/* The pixel of `scene` with adaptive sampling down to k x k leaves
 * (samples = 4 k^2) and a threshold of 0.01. */
static double adaptive_pixel(const char *tag, const char *scene, int k)
{
  char args[128], name[64];
  snprintf(args, sizeof args, "--samples %d --adaptive 0.01 --quiet", 4 * k * k);
  snprintf(name, sizeof name, "%s-%d", tag, k);
  return one_pixel(name, scene, args);
}

/* Adaptive sampling with k x k leaves (samples = 4 k^2): a square the edge
 * crosses has corners on both sides (the square is the hull of its corners),
 * so it is cut, down to the leaves; squares it does not cross are exact.
 * At most 2k - 1 leaves are crossed, each wrong by at most its area 1/k^2. */
Test(antialiasing, adaptive_squares_converge_to_the_covered_fraction)
{
  Check c = CHECK("pixel, square_mean (--adaptive T)", DOC_ADAPTIVE);
  for (int k = 2; k <= 32; k *= 2)
    CHECK_NEAR(&c, EDGE_FRACTION, adaptive_pixel("adaptive", EDGE_SCENE, k),
               (2.0 * k - 1.0) / (k * k),
               "a pixel 28%% covered by a white triangle, --samples %d --adaptive 0.01 "
               "(squares cut down to 1/%d of the pixel): red", 4 * k * k, k);
  CHECK_DONE(&c);
}

/* A vertical edge: the plane through (0.5, 0, -0.2) with that normal is hit
 * where 0.5 X + 0.2 > 0, i.e. nx > 0.3: the pixel is 70% white. With k x k
 * leaves (samples = 4 k^2), the squares the edge crosses are cut down to the
 * column of k leaves [a, a + 1/k] around x = 0.3 (a = floor(0.3 k) / k); every
 * other square is all black or all white, exact. In each leaf of the column
 * the edge leaves the fraction 1 - f white (f = frac(0.3 k)); the left
 * corners are black, the right ones white (mean 1/2), and the centre is white
 * when f < 1/2: the leaf counts e = (1/2 + [f < 1/2]) / 2. So the pixel is
 * 0.7 + (e - (1 - f)) / k exactly (no lattice point lies on the edge). */
Test(antialiasing, adaptive_squares_cut_down_to_the_leaves_along_an_edge)
{
  static const char scene[] =
      ONE_PIXEL "plane point 0.5 0 -0.2 normal 0.5 0 -0.2 material white\n";
  Check c = CHECK("square_mean", DOC_ADAPTIVE);
  for (int k = 2; k <= 32; k *= 2) {
    double f = 0.3 * k - floor(0.3 * k), e = (0.5 + (f < 0.5)) / 2.0;
    CHECK_NEAR(&c, 0.7 + (e - (1.0 - f)) / k, adaptive_pixel("vertical", scene, k), 1e-6,
               "a pixel white right of x = 0.3, --samples %d --adaptive 0.01 (leaves 1/%d of "
               "the pixel): red", 4 * k * k, k);
  }
  CHECK_DONE(&c);
}

/* A sphere of radius 0.1 at distance 1 straight ahead covers the pixel's
 * centre and none of its corners (they are 45 degrees off axis). With a
 * threshold no spread can exceed (shown colours lie in [0, 1]), the pixel is
 * never cut: (mean of the corners + centre) / 2 = (0 + 1) / 2. */
Test(antialiasing, a_square_whose_samples_agree_is_its_corners_and_centre_half_each)
{
  static const char scene[] = ONE_PIXEL "sphere center 0 0 -1 radius 0.1 material white\n";
  Check c = CHECK("square_mean", DOC_ADAPTIVE);
  CHECK_NEAR(&c, 0.5, one_pixel("centre-half", scene, "--samples 64 --adaptive 2 --quiet"),
             1e-6, "white at the pixel's centre, black at its four corners, never cut "
             "(--adaptive 2): red = (corners' mean + centre) / 2");
}

/* The summary's "N Mrays" of a render. */
static double mrays(const char *summary)
{
  const char *at = strstr(summary, " spp, ");
  cr_assert(at, "no summary line: '%s'", summary);
  return atof(at + 6);
}

/* The summary's "N spp": the camera samples traced per pixel. */
static double spp(const char *summary)
{
  const char *at = strstr(summary, " spp, ");
  cr_assert(at, "no summary line: '%s'", summary);
  while (at > summary && at[-1] != ' ')
    at--;
  return atof(at);
}

/* An 800 x 400 film of background only: every pixel's corners and centre
 * agree, so it traces its centre and shares its corners with its neighbours
 * (traced once per 16 x 16 tile): about 2 rays per pixel, 0.68 M for 0.32 M
 * pixels, against 64 per pixel (20.48 M) without adaptive sampling. */
Test(antialiasing, adaptive_costs_about_two_samples_where_the_picture_is_flat)
{
  static const char empty[] = "film 800 400\nbackground 0.2 0.3 0.4\n";
  char summary[512];
  int w, h;
  Check c = CHECK("pixel (--adaptive T)", DOC_ADAPTIVE);
  free(render("flat-on", empty, "--samples 64 --adaptive 0.01", &w, &h, summary,
              sizeof summary));
  CHECK_THAT(&c, mrays(summary) <= 0.70, "a flat 800 x 400 picture, --samples 64 --adaptive "
             "0.01: expected at most 0.70 Mrays (about 2 per pixel), got %s", summary);
  CHECK_THAT(&c, spp(summary) >= 2.0 && spp(summary) <= 2.2, "the same render: the summary's "
             "spp is the samples traced per pixel, a corner shared by four pixels and the "
             "centre (2 to 2.2), not the 64 asked for: got %s", summary);
  free(render("flat-off", empty, "--samples 64 --adaptive 0", &w, &h, summary, sizeof summary));
  CHECK_NEAR(&c, 20.48, mrays(summary), 0.005, "the same picture, --samples 64 --adaptive 0: "
             "Mrays (64 per pixel)");
  CHECK_NEAR(&c, 64.0, spp(summary), 0.0, "the same render: spp (every sample traced)");
}

/* Two renders' floats and summary lines' ray counts are the same. */
static bool same_render(const char *a_args, const char *b_args, const char *tag)
{
  int wa, ha, wb, hb;
  char ta[64], tb[64], sa[512], sb[512];
  snprintf(ta, sizeof ta, "%s-a", tag);
  snprintf(tb, sizeof tb, "%s-b", tag);
  float *a = render(ta, NULL, a_args, &wa, &ha, sa, sizeof sa);
  float *b = render(tb, NULL, b_args, &wb, &hb, sb, sizeof sb);
  bool same = wa == wb && ha == hb && !memcmp(a, b, sizeof(float) * 3 * (size_t)wa * ha) &&
              mrays(sa) == mrays(sb);
  free(a);
  free(b);
  return same;
}

Test(antialiasing, thread_count_changes_neither_the_floats_nor_the_rays, .timeout = 120)
{
  const char *modes[] = {"--adaptive 0.05", "--adaptive 0.01 --samples 256",
                         "--adaptive 0 --sampler random", "--adaptive 0 --sampler jitter",
                         "--adaptive 0 --sampler sobol"};
  Check c = CHECK("pixel", DOC_KEYS);
  for (int m = 0; m < 5; m++) {
    char a[200], b[200], tag[32];
    const char *common = "--width 150 --height 100 --samples 8";
    snprintf(a, sizeof a, "%s %s --threads 1", common, modes[m]);
    snprintf(b, sizeof b, "%s %s --threads 3", common, modes[m]);
    snprintf(tag, sizeof tag, "threads-%d", m);
    CHECK_THAT(&c, same_render(a, b, tag), "the default scene at 150 x 100, %s: --threads 1 "
               "and --threads 3 gave different floats or ray counts", modes[m]);
  }
  CHECK_DONE(&c);
}

Test(antialiasing, the_seed_changes_the_noise_and_only_the_seed)
{
  const char *base = "--width 64 --height 48 --samples 4 --sampler jitter --adaptive 0";
  char a[160], b[160];
  snprintf(a, sizeof a, "%s --seed 7", base);
  snprintf(b, sizeof b, "%s --seed 8", base);
  Check c = CHECK("pixel (--adaptive 0)", DOC_KEYS);
  CHECK_THAT(&c, same_render(a, a, "seed-same"), "jitter, seed 7 twice: the pictures differ");
  CHECK_THAT(&c, !same_render(a, b, "seed-other"), "jitter, seeds 7 and 8: the same picture");
}
