/* Root mean square difference of two images of the same size, both clamped to
 * [0, 1] per channel (what a display shows), for the benchmark's error
 * columns. .pfm is read exactly; .png (8 or 16 bits, POV-Ray writes 16 with
 * File_Gamma=1.0) through stb_image. Usage: rmse A B  -> prints the RMSE. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stb_image.h>

#include "app/image.h"

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
  *rgb = malloc((size_t)*w * *h * 3 * sizeof **rgb);
  for (size_t k = 0; *rgb && k < (size_t)*w * *h * 3; k++)
    (*rgb)[k] = (float)px[k] / 65535.0f;
  stbi_image_free(px);
  return *rgb != NULL;
}

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

int main(int argc, char **argv)
{
  int wa, ha, wb, hb;
  float *a = NULL, *b = NULL;
  if (argc != 3) {
    fprintf(stderr, "usage: rmse A B\n");
    return 2;
  }
  if (!load(argv[1], &wa, &ha, &a) || !load(argv[2], &wb, &hb, &b))
    return 1;
  if (wa != wb || ha != hb) {
    fprintf(stderr, "rmse: sizes differ: %dx%d and %dx%d\n", wa, ha, wb, hb);
    return 1;
  }
  /* PFM rows are stored bottom-up and PNG rows top-down: image_load gives
   * both bottom-up (the film's order), stb gives top-down; flip PNG rows. */
  double sum = 0.0;
  size_t n = (size_t)wa * ha * 3;
  for (int j = 0; j < ha; j++)
    for (int i = 0; i < wa * 3; i++) {
      size_t ka = (size_t)j * wa * 3 + i, kb = ka;
      bool a_png = strstr(argv[1], ".pfm") == NULL, b_png = strstr(argv[2], ".pfm") == NULL;
      if (a_png != b_png)
        kb = (size_t)(ha - 1 - j) * wa * 3 + i;
      double d = clamp01(a[ka]) - clamp01(b[kb]);
      sum += d * d;
    }
  printf("%.6e\n", sqrt(sum / (double)n));
  free(a);
  free(b);
  return 0;
}
