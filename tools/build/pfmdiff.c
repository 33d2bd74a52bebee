/* How far render A is from B, as the image test measures it, and float for
 * float: for tools/build/platforms.sh, which compares renders made on other
 * systems, compilers and CPUs with images/ and with each other.
 * Usage: pfmdiff A B [TOL FRACTION MAX]. A and B are .pfm or .png
 * (docs/testing.md, "The image test"): both clamped to [0, 1] as the PNG
 * export does, then compared channel by channel in 1/255 units. Prints one
 * line: the largest difference, the share of channels over TOL and, for two
 * .pfm, how many floats differ at all (and by how much, unclamped). Exit 0 when no
 * channel exceeds MAX and at most FRACTION of them exceed TOL (the image
 * test's defaults: 1.5 0.001 16), 1 otherwise, 2 when a file cannot be read
 * or the sizes differ. MAX 0 between two .pfm asks for every float equal,
 * those past 1 included. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/image.h"

static double clamp01(float x)
{
  return x != x ? 1e9 : fmin(fmax((double)x, 0.0), 1.0);
}

static bool pfm(const char *path)
{
  size_t n = strlen(path);
  return n > 4 && strcmp(path + n - 4, ".pfm") == 0;
}

int main(int argc, char **argv)
{
  if (argc != 3 && argc != 6) {
    fprintf(stderr, "usage: pfmdiff A B [TOL FRACTION MAX]\n");
    return 2;
  }
  double tol = argc == 6 ? atof(argv[3]) : 1.5, fraction = argc == 6 ? atof(argv[4]) : 0.001;
  double max_allowed = argc == 6 ? atof(argv[5]) : 16.0;
  int wa, ha, wb, hb;
  float *a, *b;
  if (!image_load(argv[1], &wa, &ha, &a) || !image_load(argv[2], &wb, &hb, &b))
    return 2;
  if (wa != wb || ha != hb) {
    printf("%s is %dx%d, %s is %dx%d\n", argv[1], wa, ha, argv[2], wb, hb);
    return 2;
  }
  long n = 3L * wa * ha, over = 0, differ = 0;
  double worst = 0.0, worst_raw = 0.0;
  for (long k = 0; k < n; k++) {
    double e = 255.0 * fabs(clamp01(a[k]) - clamp01(b[k]));
    worst = fmax(worst, e);
    over += e > tol;
    if (a[k] != b[k]) {
      differ++;
      double raw = fabs((double)a[k] - (double)b[k]);
      worst_raw = raw == raw ? fmax(worst_raw, raw) : INFINITY;
    }
  }
  bool ok = worst <= max_allowed && (double)over <= fraction * (double)n;
  if (max_allowed == 0.0 && pfm(argv[1]) && pfm(argv[2]))
    ok = ok && differ == 0;
  printf("%s: max %.3f/255, %ld of %ld channels over %.3g/255", ok ? "within" : "OUTSIDE",
         worst, over, n, tol);
  if (pfm(argv[1]) && pfm(argv[2]))
    printf("; %ld floats differ (largest by %.3g)", differ, worst_raw);
  printf("\n");
  free(a);
  free(b);
  return ok ? 0 : 1;
}
