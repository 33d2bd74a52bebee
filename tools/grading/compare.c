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
          "       grade-compare noise RATIO PREFIX YOURS REF1 REF2 REF3 [REF...]\n"
          "TOL and MAX in 1/255 units; REF a .pfm or .png; RATIO: to the solution's own level.\n");
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

enum { BLOCK = 8 };     /* pixels on a side of the blocks the bias test sums over */
static const double Z_CAP = 5.0; /* a pixel's standardized difference is clamped to +-5 */

/* Per channel, the mean and the unbiased variance of n renders. */
static void mean_var(const Picture *const *refs, int n, Picture *mean, float *var)
{
  for (size_t c = 0; c < (size_t)mean->w * mean->h * 3; c++) {
    double m = 0.0, m2 = 0.0;
    for (int k = 0; k < n; k++)
      m += refs[k]->rgb[c];
    m /= n;
    for (int k = 0; k < n; k++)
      m2 += (refs[k]->rgb[c] - m) * (refs[k]->rgb[c] - m);
    mean->rgb[c] = (float)m;
    var[c] = (float)(m2 / (n - 1));
  }
}

/* The bias statistic of y against n renders: per channel and pixel the
 * difference from their mean in units of its standard deviation,
 * z = (y - M) / sqrt((1 + 1/n)(v + f^2)), f = 0.5/255, clamped to +-Z_CAP (a
 * rare event, such as a light edge that n renders never hit, counts once,
 * not without bound); summed over each BLOCK x BLOCK block as
 * Z = sum z / sqrt(count). Noise averages out of Z, a bias adds up in it.
 * Returns the mean of Z^2 over the blocks; the block with the largest |Z|
 * gives *x, *yy (its centre, y from the top). */
static double bias_stat(const Picture *y, const Picture *const *refs, int n, int *x, int *yy)
{
  const double f2 = (0.5 / 255.0) * (0.5 / 255.0);
  size_t len = (size_t)y->w * y->h * 3;
  Picture mean = {y->w, y->h, malloc(len * sizeof(float))};
  float *var = malloc(len * sizeof(float));
  mean_var(refs, n, &mean, var);
  double sum = 0.0, zmax = -1.0;
  int blocks = 0;
  for (int bj = 0; bj < y->h; bj += BLOCK)
    for (int bi = 0; bi < y->w; bi += BLOCK)
      for (int c = 0; c < 3; c++) {
        double zs = 0.0;
        int count = 0;
        for (int j = bj; j < bj + BLOCK && j < y->h; j++)
          for (int i = bi; i < bi + BLOCK && i < y->w; i++, count++) {
            size_t k = 3 * ((size_t)j * y->w + i) + c;
            double z = (y->rgb[k] - mean.rgb[k]) / sqrt((1.0 + 1.0 / n) * (var[k] + f2));
            zs += fmin(fmax(z, -Z_CAP), Z_CAP);
          }
        double z = zs / sqrt(count);
        sum += z * z;
        blocks++;
        if (fabs(z) > zmax) {
          zmax = fabs(z);
          *x = bi + BLOCK / 2 < y->w ? bi + BLOCK / 2 : y->w - 1;
          *yy = y->h - 1 - (bj + BLOCK / 2 < y->h ? bj + BLOCK / 2 : y->h - 1);
        }
      }
  picture_free(&mean);
  free(var);
  return sum / blocks;
}

/* Steps 07-08: the render against K solution renders of other seeds. What
 * bias_stat gives a correct render is learnt from the solution itself: each
 * S_k against the other K - 1 (leave one out); their mean is the level H0.
 * The submission passes when its statistic is at most RATIO times H0
 * (docs/grading.md, "Tolerances", has the measurements behind RATIO = 2.5). */
static int noise(int argc, char **argv)
{
  double ratio = atof(argv[0]);
  int k_refs = argc - 3;
  Picture y = {0}, *s = calloc((size_t)k_refs, sizeof *s);
  const Picture **refs = calloc((size_t)k_refs, sizeof *refs);
  bool ok = s && refs && k_refs >= 3 && picture_load(argv[2], &y);
  for (int k = 0; ok && k < k_refs; k++) {
    ok = picture_load(argv[3 + k], &s[k]) && same_size(&y, &s[k], argv[3 + k]);
    refs[k] = &s[k];
  }
  int status = 1;
  if (ok) {
    int x = 0, yy = 0, lx, ly;
    double h0 = 0.0;
    for (int k = 0; k < k_refs; k++) { /* S_k first, then the others */
      const Picture *tmp = refs[0];
      refs[0] = refs[k];
      refs[k] = tmp;
      h0 += bias_stat(refs[0], refs + 1, k_refs - 1, &lx, &ly) / k_refs;
    }
    double stat = bias_stat(&y, refs, k_refs, &x, &yy);
    size_t n = (size_t)y.w * y.h * 3;
    Picture mean = {y.w, y.h, malloc(n * sizeof(float))};
    float *var = malloc(n * sizeof(float));
    mean_var(refs, k_refs, &mean, var);
    double noise_ms = 0.0, err_ms = 0.0;
    for (size_t c = 0; c < n; c++) {
      noise_ms += var[c] / (double)n;
      err_ms += ((double)y.rgb[c] - mean.rgb[c]) * ((double)y.rgb[c] - mean.rgb[c]) / (double)n;
    }
    printf("pass=%d size=%dx%d ratio=%.2f allowed=%.2f stat=%.3f h0=%.3f noise=%.3f rmse=%.3f "
           "seeds=%d worst_x=%d worst_y=%d\n", stat <= ratio * h0, y.w, y.h, stat / h0, ratio, stat,
           h0, 255.0 * sqrt(noise_ms), 255.0 * sqrt(err_ms), k_refs, x, yy);
    status = save_pictures(argv[1], &y, &mean, (float)(4.0 * sqrt(noise_ms) + 1.5 / 255.0)) ? 0 : 1;
    picture_free(&mean);
    free(var);
  }
  for (int k = 0; s && k < k_refs; k++)
    picture_free(&s[k]);
  free(s);
  free(refs);
  picture_free(&y);
  return status;
}

int main(int argc, char **argv)
{
  if (argc == 8 && strcmp(argv[1], "exact") == 0)
    return exact(argv + 2);
  if (argc >= 8 && strcmp(argv[1], "noise") == 0)
    return noise(argc - 2, argv + 2);
  return usage();
}
