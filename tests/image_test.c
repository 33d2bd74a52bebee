/* The image test of every step (compiled once per step with STEP_NAME and
 * BUILD_DIR): render the step's default scene at the reference image's size
 * and compare it with images/STEP_NAME.png; render it again as a PNG and check
 * every byte against the floats of the .pfm. docs/testing.md, "The image test".
 *
 * Options. The command line is `--width W --height H --threads 2 --quiet`
 * plus the step's IMAGE_ARGS (steps/STEP_NAME/step.mk, the step's manifest,
 * through build/gen/STEP_NAME/step_manifest.h); `make regen` renders the
 * reference with the same ones.
 *
 * Tolerance. The binary writes a .pfm (the film's exact floats); each float is
 * clamped to [0, 1] (what the PNG export does) and compared with the
 * reference byte / 255. A render identical to the reference's differs by at
 * most 0.5/255 (the byte's rounding). Another compiler, -march or libm may
 * move a value across a rounding boundary: 1.5/255 then still passes. A
 * channel may exceed 1.5/255 in at most 0.1% of channels (a silhouette pixel
 * whose ray grazes a sphere can flip between two objects), but never 16/255:
 * a wrong formula moves whole regions by far more than that. These are the
 * manifest's IMAGE_TOL "1.5 0.001 16" (TOL FRACTION MAX, TOL and MAX in 1/255
 * units); a noisy step sets its own there. */
#include "check.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <stb_image.h>

#include "app/image.h"
#include "step_manifest.h"
#include "terms.h"

#define REF_PATH "images/" STEP_NAME ".png"
#define OUT_DIR BUILD_DIR "/test-out"
#define DIFF_PATH BUILD_DIR "/diff/" STEP_NAME ".png"

/* Each step's own functions (its solution regions), and the doc that lists
 * them: what a failing picture of that step points at first. */
static const struct {
  const char *step, *functions, *doc;
} STEP_CODE[] = {
    {"01-film", "pixel, film_sample", "docs/01-film.md"},
    {"02-intersection", "sphere_hit_t, sphere_hit_fill, plane_hit_t, plane_hit_fill",
     "docs/02-intersection.md"},
    {"03-camera", "camera_init, camera_ray", "docs/03-camera.md"},
    {"04-phong", "light_incident, shade_phong_light, shade_phong", "docs/04-phong.md"},
    {"05-shadows", "shade_visible, ray_spawn", "docs/05-shadows.md"},
    {"06-ambient", "shade_phong, shade_trace", "docs/06-ambient.md"},
    {"07-antialiasing", "antialias_pixel, pixel_sampled, square_mean, point_colour",
     "docs/07-antialiasing.md"},
    {"08-area-lights", "shade_area, area_incident, shade_light, shade_trace",
     "docs/08-area-lights.md"},
};
enum { N_STEPS = sizeof STEP_CODE / sizeof STEP_CODE[0] };

static int step_index(void)
{
  for (int k = 0; k < N_STEPS; k++)
    if (strcmp(STEP_CODE[k].step, STEP_NAME) == 0)
      return k;
  return 0;
}

/* The functions of the steps before this one, "a, b (step 02); c (step 03)". */
static void earlier_functions(char *out, size_t size)
{
  out[0] = 0;
  for (int k = 1; k < step_index(); k++) {
    size_t len = strlen(out);
    snprintf(out + len, size - len, "%s%s (step %.2s)", k > 1 ? "; " : "",
             STEP_CODE[k].functions, STEP_CODE[k].step);
  }
}

typedef struct Tolerance {
  double tol, fraction, max; /* tol and max in 1/255 units */
} Tolerance;

/* The step's tolerance: the manifest's IMAGE_TOL. */
static Tolerance tolerance(void)
{
  return (Tolerance){STEP_IMAGE_TOL, STEP_IMAGE_FRACTION, STEP_IMAGE_MAX};
}

/* The step's extra options: the manifest's IMAGE_ARGS (tools/build/manifest.sh
 * allows option characters only). */
static void step_args(char *out, size_t size)
{
  snprintf(out, size, "%s", STEP_IMAGE_ARGS);
}

/* Render the step's default scene at w x h to `path` (.pfm or .png). What the
 * program says on stderr (such as "ignoring the lights") is shown only when
 * it fails. */
static void render(int w, int h, const char *path)
{
  char args[256], cmd[1024], said[512] = "";
  const char *err_path = OUT_DIR "/" STEP_NAME "-stderr.txt";
  step_args(args, sizeof args);
  mkdir(OUT_DIR, 0755);
  remove(path);
  snprintf(cmd, sizeof cmd, "%s/bin/%s --width %d --height %d --threads 2 --quiet %s -o %s",
           BUILD_DIR, STEP_NAME, w, h, args, path);
  char run[1200];
  snprintf(run, sizeof run, "%s 2> %s", cmd, err_path);
  int status = system(run);
  bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  FILE *f = ok ? NULL : fopen(err_path, "r");
  if (f) {
    size_t n = fread(said, 1, sizeof said - 1, f);
    said[n] = 0;
    fclose(f);
  }
  cr_assert(ok, "the step's program failed: '%s' (exit status %d)%s%s\n  read %s, \"What you "
            "write\"", cmd, WIFEXITED(status) ? WEXITSTATUS(status) : -1,
            said[0] ? "; it said:\n" : "", said, STEP_CODE[step_index()].doc);
}

/* The reference image's size: the manifest's IMAGE_SIZE. */
static void reference_size(int *w, int *h)
{
  *w = STEP_IMAGE_WIDTH;
  *h = STEP_IMAGE_HEIGHT;
}

Test(reference_image, render_matches_the_reference, .timeout = 300)
{
  const char *out_path = OUT_DIR "/" STEP_NAME ".pfm";
  int rw, rh, w, h;
  float *ref, *out;
  cr_assert(image_load(REF_PATH, &rw, &rh, &ref), "no reference image %s (run make regen)",
            REF_PATH);
  reference_size(&w, &h);
  cr_assert(w == rw && h == rh, "%s is %dx%d, steps/" STEP_NAME "/step.mk's IMAGE_SIZE %dx%d "
            "(run make regen)", REF_PATH, rw, rh, w, h);
  render(rw, rh, out_path);
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
    image_save_diff(DIFF_PATH, w, h, out, ref, (float)(t.tol / 255.0), 8.0f);
  } else {
    remove(DIFF_PATH); /* no stale picture from an earlier failure */
  }
  char terms[2048], args[256];
  step_args(args, sizeof args);
  terms_after_image_test(w, h, out, ref, t.tol, t.fraction, t.max, pass, args, terms,
                         sizeof terms);
  cr_log_info("%s: %dx%d, %ld of %zu channels over %.2f/255 (%.4f%%, allowed %.4f%%), "
              "max %.2f/255 (allowed %.2f/255), rmse %.3f/255", STEP_NAME, w, h,
              d.over, n, t.tol, 100.0 * over, 100.0 * t.fraction,
              255.0 * d.max_abs, t.max, 255.0 * d.rmse);
  char earlier[512], doc[96];
  earlier_functions(earlier, sizeof earlier);
  snprintf(doc, sizeof doc, "%s, \"What you write\"", STEP_CODE[step_index()].doc);
  Check c = CHECK(STEP_CODE[step_index()].functions, doc);
  CHECK_THAT(&c, pass,
             "the render of %s differs from %s\n"
             "  %ld of %zu channels (%.2f%%) differ by more than %.1f/255 (allowed %.2f%%)\n"
             "  largest difference %.1f/255 (allowed %.0f/255), rmse %.2f/255\n"
             "  diff picture: %s (red: over the tolerance)%s%s%s%s%s",
             STEP_NAME, REF_PATH, d.over, n, 100.0 * over, t.tol, 100.0 * t.fraction,
             255.0 * d.max_abs, t.max, 255.0 * d.rmse, DIFF_PATH,
             earlier[0] ? "\n  the picture also goes through the earlier steps' " : "",
             earlier[0] ? earlier : "",
             earlier[0] ? ": when their unit tests fail too, fix those first" : "",
             terms[0] ? "\n" : "", terms);
  free(ref);
  free(out);
}

/* round(255 clamp(c, 0, 1)), halves up, in double (255 c is exact there).
 * *alt is the other byte a float computation of 255 c may give when it can
 * round across the half (else the same byte): both are right. */
static int expected_byte(float c, int *alt)
{
  double x = c > 0.0f ? 255.0 * fmin((double)c, 1.0) : 0.0; /* NaN and negatives: 0 */
  double k = floor(x);
  int want = (int)k + (x - k >= 0.5);
  bool near_half = fabs(x - k - 0.5) <= x * 0x1p-24;
  *alt = near_half ? (want == (int)k ? want + 1 : want - 1) : want;
  return want;
}

/* At half the reference size (a quarter of the pixels, still tens of
 * thousands of values): the film is rendered twice, once per format. */
Test(reference_image, png_bytes_are_the_rounded_film, .timeout = 300)
{
  const char *pfm_path = OUT_DIR "/" STEP_NAME "-bytes.pfm";
  const char *png_path = OUT_DIR "/" STEP_NAME "-bytes.png";
  int w, h, pw, ph, n;
  reference_size(&w, &h);
  w = (w + 1) / 2;
  h = (h + 1) / 2;
  render(w, h, pfm_path);
  render(w, h, png_path);
  float *film;
  cr_assert(image_load(pfm_path, &w, &h, &film), "cannot read the render %s", pfm_path);
  unsigned char *png = stbi_load(png_path, &pw, &ph, &n, 3);
  cr_assert(png && pw == w && ph == h, "cannot read %s as a %dx%d PNG", png_path, w, h);
  Check c = CHECK("film_to_byte", "docs/01-film.md, \"What you write\"");
  static const char channel[3] = {'R', 'G', 'B'};
  for (int y = 0; y < h; y++) /* y from the top, as the PNG stores it */
    for (int x = 0; x < w; x++)
      for (int ch = 0; ch < 3; ch++) {
        float v = film[((size_t)(h - 1 - y) * w + x) * 3 + ch];
        int got = png[((size_t)y * w + x) * 3 + ch];
        int alt, want = expected_byte(v, &alt);
        CHECK_THAT(&c, got == want || got == alt,
                   "pixel (%d, %d) (from the top left) channel %c of %s's PNG: the film "
                   "holds %.9g, so the byte is round(255 clamp(c, 0, 1)) = %d\n"
                   "  expected %d\n  got      %d",
                   x, y, channel[ch], STEP_NAME, v, want, want, got);
      }
  CHECK_DONE(&c);
  stbi_image_free(png);
  free(film);
}
