/* Root mean square difference of an image and a reference of the same size,
 * both clamped to [0, 1] per channel (what a display shows), for the
 * benchmark's error columns. With several reference files the reference is
 * their mean (independent renders of an unbiased estimate: less noise).
 * .pfm is read exactly; .png (8 or 16 bits, POV-Ray writes 16 with
 * File_Gamma=1.0) through stb_image. Usage: rmse A REF [REF...] -> the RMSE. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stb_image.h>

#include "app/image.h"

/* The image at `path`, rows bottom-up (the film's order) whatever the file. */
static bool load(const char *path, int *w, int *h, float **rgb)
{
  size_t len = strlen(path);
  if (len > 4 && strcmp(path + len - 4, ".pfm") == 0)
    return image_load(path, w, h, rgb);
  int n;
  unsigned short *px = stbi_load_16(path, w, h, &n, 3);
  if (!px) {
    fprintf(stderr, "rmse: cannot read '%s'\n", path);
    return false;
  }
  size_t row = (size_t)*w * 3;
  *rgb = malloc(row * (size_t)*h * sizeof **rgb);
  for (int j = 0; *rgb && j < *h; j++) /* PNG rows are top-down */
    for (size_t i = 0; i < row; i++)
      (*rgb)[(size_t)(*h - 1 - j) * row + i] = (float)px[(size_t)j * row + i] / 65535.0f;
  stbi_image_free(px);
  return *rgb != NULL;
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

int main(int argc, char **argv)
{
  int wa, ha, wb, hb;
  float *a = NULL, *b = NULL;
  if (argc < 3) {
    fprintf(stderr, "usage: rmse A REF [REF...]\n");
    return 2;
  }
  if (!load(argv[1], &wa, &ha, &a))
    return 1;
  size_t n = (size_t)wa * ha * 3;
  double *ref = calloc(n, sizeof *ref);
  for (int r = 2; r < argc; r++) {
    if (!ref || !load(argv[r], &wb, &hb, &b))
      return 1;
    if (wa != wb || ha != hb) {
      fprintf(stderr, "rmse: sizes differ: %dx%d and %dx%d\n", wa, ha, wb, hb);
      return 1;
    }
    for (size_t k = 0; k < n; k++)
      ref[k] += (double)b[k] / (argc - 2);
    free(b);
  }
  double sum = 0.0;
  for (size_t k = 0; k < n; k++) {
    double d = clamp01(a[k]) - clamp01(ref[k]);
    sum += d * d;
  }
  printf("%.6e\n", sqrt(sum / (double)n));
  free(a);
  free(ref);
  return 0;
}
