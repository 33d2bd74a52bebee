/* The grader's picture comparison (make grade; docs/grading.md, "Tolerances"):
 * a student's render (.pfm) against the solution's, as floats clamped to
 * [0, 1], with the step's fixed tolerance (steps 01-06) or against the
 * solution's own seed-to-seed noise (steps 07-08). Writes the expected, yours
 * and difference pictures, and names the worst pixel for --trace. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/image.h"

typedef struct Picture {
  int w, h;
  float *rgb; /* clamped to [0, 1], NaN as 2 (always over any tolerance) */
} Picture;

static int usage(void)
{
  fprintf(stderr,
          "usage: grade-compare exact TOL FRACTION MAX PREFIX YOURS REF\n"
          "       grade-compare noise Z PREFIX YOURS REF1 REF2 [REF...]\n"
          "TOL and MAX in 1/255 units; REF a .pfm or .png; Z in standard deviations.\n");
  return 2;
}

static void picture_free(Picture *p)
{
  free(p->rgb);
  p->rgb = NULL;
}

/* Load and clamp; false (and one line on stderr) when unreadable. */
static bool picture_load(const char *path, Picture *p)
{
  if (!image_load(path, &p->w, &p->h, &p->rgb))
    return false;
  for (size_t k = 0; k < (size_t)p->w * p->h * 3; k++) {
    float c = p->rgb[k];
    p->rgb[k] = c != c ? 2.0f : fminf(fmaxf(c, 0.0f), 1.0f);
  }
  return true;
}

static bool same_size(const Picture *a, const Picture *b, const char *path)
{
  if (a->w == b->w && a->h == b->h)
    return true;
  printf("pass=0 reason=size yours=%dx%d expected=%dx%d (%s)\n", a->w, a->h, b->w, b->h, path);
  return false;
}

/* The pixel where the difference, box-averaged over (2r+1)^2 pixels to see a
 * bias through noise (r = 0: no averaging), is largest; x from the left, y
 * from the top, as --trace takes them. */
static void worst_pixel(const Picture *a, const Picture *b, int r, int *x, int *y)
{
  double best = -1.0;
  for (int j = 0; j < a->h; j++)
    for (int i = 0; i < a->w; i++) {
      double s[3] = {0.0, 0.0, 0.0};
      for (int dj = -r; dj <= r; dj++)
        for (int di = -r; di <= r; di++) {
          int ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= a->w || jj >= a->h)
            continue;
          size_t k = 3 * ((size_t)jj * a->w + ii);
          for (int c = 0; c < 3; c++)
            s[c] += (double)a->rgb[k + c] - b->rgb[k + c];
        }
      double e = fmax(fabs(s[0]), fmax(fabs(s[1]), fabs(s[2])));
      if (e > best) {
        best = e;
        *x = i;
        *y = a->h - 1 - j;
      }
    }
}

static bool save_pictures(const char *prefix, const Picture *yours, const Picture *expected,
                          float tol)
{
  char path[4096];
  snprintf(path, sizeof path, "%s-yours.png", prefix);
  bool ok = image_save(path, yours->w, yours->h, yours->rgb, TONEMAP_CLAMP);
  snprintf(path, sizeof path, "%s-expected.png", prefix);
  ok = image_save(path, expected->w, expected->h, expected->rgb, TONEMAP_CLAMP) && ok;
  snprintf(path, sizeof path, "%s-diff.png", prefix);
  return image_save_diff(path, yours->w, yours->h, yours->rgb, expected->rgb, tol, 8.0f) && ok;
}

/* Steps 01-06: every channel within TOL, except FRACTION of them, none beyond
 * MAX (the image test's rule, tests/image_test.c). */
static int exact(char **argv)
{
  double tol = atof(argv[0]) / 255.0, fraction = atof(argv[1]), max = atof(argv[2]) / 255.0;
  Picture y = {0}, e = {0};
  if (!picture_load(argv[4], &y) || !picture_load(argv[5], &e))
    return 1;
  int status = 1;
  if (same_size(&y, &e, argv[5])) {
    ImageDiff d = image_compare(y.w, y.h, y.rgb, e.rgb, (float)tol);
    double over = (double)d.over / (3.0 * y.w * y.h);
    int x = 0, yy = 0;
    worst_pixel(&y, &e, 0, &x, &yy);
    printf("pass=%d size=%dx%d over=%ld fraction=%.6f allowed_fraction=%.6f max=%.2f "
           "allowed_max=%.2f tol=%.2f rmse=%.3f worst_x=%d worst_y=%d\n",
           over <= fraction && d.max_abs <= max, y.w, y.h, d.over, over, fraction,
           255.0 * d.max_abs, 255.0 * max, 255.0 * tol, 255.0 * d.rmse, x, yy);
    status = save_pictures(argv[3], &y, &e, (float)tol) ? 0 : 1;
  }
  picture_free(&y);
  picture_free(&e);
  return status;
}

/* Mean square difference between a and b over all channels. */
static double mean_square(const float *a, const float *b, size_t n)
{
  double s = 0.0;
  for (size_t k = 0; k < n; k++)
    s += ((double)a[k] - b[k]) * ((double)a[k] - b[k]);
  return s / (double)n;
}

/* Steps 07-08. K solution renders S_k (different seeds), their mean M. A
 * correct render Y (another seed) has E[(Y - M)^2] = s2 (1 + 1/K), s2 the
 * per-channel noise variance; solution k against the mean of the others has
 * E = s2 (1 + 1/(K-1)). Both are scaled to estimate s2; Y passes when its
 * estimate is within Z standard deviations of the solution's K estimates
 * (plus (0.5/255)^2, so that a nearly noiseless scene is not held to zero). */
static int noise(int argc, char **argv)
{
  double z = atof(argv[0]);
  int k_refs = argc - 3;
  Picture y = {0}, *s = calloc((size_t)k_refs, sizeof *s);
  bool ok = s && picture_load(argv[2], &y);
  for (int k = 0; ok && k < k_refs; k++)
    ok = picture_load(argv[3 + k], &s[k]) && same_size(&y, &s[k], argv[3 + k]);
  int status = 1;
  if (ok) {
    size_t n = (size_t)y.w * y.h * 3;
    Picture mean = {y.w, y.h, calloc(n, sizeof(float))}, rest = {y.w, y.h, malloc(n * sizeof(float))};
    for (int k = 0; k < k_refs; k++)
      for (size_t c = 0; c < n; c++)
        mean.rgb[c] += s[k].rgb[c] / (float)k_refs;
    double sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < k_refs; k++) {
      for (size_t c = 0; c < n; c++)
        rest.rgb[c] = (float)(((double)k_refs * mean.rgb[c] - s[k].rgb[c]) / (k_refs - 1));
      double est = mean_square(s[k].rgb, rest.rgb, n) * (k_refs - 1) / k_refs;
      sum += est;
      sum2 += est * est;
    }
    double avg = sum / k_refs, sd = sqrt(fmax(0.0, (sum2 - k_refs * avg * avg) / (k_refs - 1)));
    double yours = mean_square(y.rgb, mean.rgb, n) * k_refs / (k_refs + 1.0);
    double floor = (0.5 / 255.0) * (0.5 / 255.0), allowed = avg + z * sd + floor;
    int x = 0, yy = 0;
    worst_pixel(&y, &mean, 2, &x, &yy);
    printf("pass=%d size=%dx%d noise=%.3f noise_sd=%.3f yours=%.3f allowed=%.3f seeds=%d "
           "worst_x=%d worst_y=%d\n", yours <= allowed, y.w, y.h, 255.0 * sqrt(avg),
           255.0 * (sd / (2.0 * sqrt(fmax(avg, 1e-30)))), 255.0 * sqrt(yours),
           255.0 * sqrt(allowed), k_refs, x, yy);
    status = save_pictures(argv[1], &y, &mean, (float)(3.0 * sqrt(allowed))) ? 0 : 1;
    picture_free(&mean);
    picture_free(&rest);
  }
  for (int k = 0; s && k < k_refs; k++)
    picture_free(&s[k]);
  free(s);
  picture_free(&y);
  return status;
}

int main(int argc, char **argv)
{
  if (argc == 8 && strcmp(argv[1], "exact") == 0)
    return exact(argv + 2);
  if (argc >= 7 && strcmp(argv[1], "noise") == 0)
    return noise(argc - 2, argv + 2);
  return usage();
}
