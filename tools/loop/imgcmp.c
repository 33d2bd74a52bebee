/* Compare two images pixel by pixel, as decoded bytes (not file bytes: two
 * PNG encoders may compress the same pixels differently), and write the
 * pictures the repository keeps (make regen, make check-derived;
 * tools/figures/images.sh, tools/figures/docimg.sh).
 *   imgcmp A B           exit 0 when every channel is equal, 1 when some
 *                        differ (one line says how), 2 when a file cannot be
 *                        read or the sizes differ
 *   imgcmp --edge N,T,F ...  before either form: the pictures also agree
 *                        when at most a fraction F of the pixels differ and
 *                        every N x N block's mean is within T codes (a picture
 *                        of shadow acne, on a knife edge: agree() says why)
 *   imgcmp --put KEPT NEW  write KEPT from NEW's pixels (image_save_kept, the
 *                        one writer of kept pictures) when it is missing, of
 *                        another size or differs in any channel; one line
 *                        "regen: wrote KEPT (why)" when it writes, nothing
 *                        otherwise; exit 0, or 2 on an error
 *   imgcmp --recode FILE...  rewrite each PNG from its own pixels through
 *                        image_save_kept (the same pixels, the one writer's bytes) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/image.h"

typedef struct Picture {
  int w, h;
  float *rgb;
} Picture;

/* Pixels that differ in any channel's byte, and the largest difference. */
static long differ(const Picture *a, const Picture *b, long *max_codes)
{
  long pixels = 0;
  *max_codes = 0;
  for (long p = 0; p < (long)a->w * a->h; p++) {
    long worst = 0;
    for (int c = 0; c < 3; c++) {
      long codes = labs(lroundf(255.0f * a->rgb[3 * p + c]) - lroundf(255.0f * b->rgb[3 * p + c]));
      worst = codes > worst ? codes : worst;
    }
    pixels += worst > 0;
    *max_codes = worst > *max_codes ? worst : *max_codes;
  }
  return pixels;
}

/* The largest difference, in codes, between the means of a channel over the
 * same n x n block of the two pictures (blocks cut at the right and bottom
 * edges). */
static double block_mean_diff(const Picture *a, const Picture *b, int n)
{
  double worst = 0.0;
  for (int y0 = 0; y0 < a->h; y0 += n) {
    for (int x0 = 0; x0 < a->w; x0 += n) {
      double sum[3] = {0.0, 0.0, 0.0};
      int count = 0;
      for (int y = y0; y < y0 + n && y < a->h; y++) {
        for (int x = x0; x < x0 + n && x < a->w; x++, count++) {
          long p = (long)y * a->w + x;
          for (int c = 0; c < 3; c++)
            sum[c] += lroundf(255.0f * a->rgb[3 * p + c]) - lroundf(255.0f * b->rgb[3 * p + c]);
        }
      }
      for (int c = 0; c < 3; c++)
        worst = fmax(worst, fabs(sum[c]) / count);
    }
  }
  return worst;
}

/* The knife-edge tolerance (--edge N,T,F), for a picture of shadow acne,
 * whose pixels each fall lit or dark on the last bit of a hit point: the
 * pictures agree when at most a fraction F of the pixels differ, and every
 * N x N block's mean differs by at most T codes in every channel (the same
 * density of acne, wherever its pixels fall). */
static int edge_n;
static double edge_t, edge_f;

/* Whether a and b agree: equal in every channel, or within the knife-edge
 * tolerance when one is set. */
static bool agree(const Picture *a, const Picture *b, long pixels, double *block)
{
  *block = 0.0;
  if (pixels == 0)
    return true;
  if (edge_n <= 0)
    return false;
  *block = block_mean_diff(a, b, edge_n);
  return *block <= edge_t && (double)pixels <= edge_f * a->w * a->h;
}

static int put(const char *kept, const char *new_path)
{
  Picture n, k = {0, 0, NULL};
  if (!image_load(new_path, &n.w, &n.h, &n.rgb))
    return 2;
  char why[160];
  if (access(kept, F_OK) != 0) {
    snprintf(why, sizeof why, "new");
  } else if (!image_load(kept, &k.w, &k.h, &k.rgb)) {
    snprintf(why, sizeof why, "unreadable before");
  } else if (k.w != n.w || k.h != n.h) {
    snprintf(why, sizeof why, "%dx%d, was %dx%d", n.w, n.h, k.w, k.h);
  } else {
    long max_codes, pixels = differ(&k, &n, &max_codes);
    double block;
    if (agree(&k, &n, pixels, &block)) {
      free(k.rgb);
      free(n.rgb);
      return 0;
    }
    snprintf(why, sizeof why, "%ld of %ld pixels changed, by up to %ld code%s", pixels,
             (long)n.w * n.h, max_codes, max_codes == 1 ? "" : "s");
  }
  bool ok = image_save_kept(kept, n.w, n.h, n.rgb);
  if (ok)
    printf("regen: wrote %s (%s)\n", kept, why);
  free(k.rgb);
  free(n.rgb);
  return ok ? 0 : 2;
}

int main(int argc, char **argv)
{
  if (argc >= 3 && strcmp(argv[1], "--edge") == 0) {
    if (sscanf(argv[2], "%d,%lf,%lf", &edge_n, &edge_t, &edge_f) != 3 || edge_n < 1 ||
        !(edge_t >= 0.0) || !(edge_f >= 0.0 && edge_f <= 1.0)) {
      fprintf(stderr, "imgcmp: --edge N,T,F: a block size, its mean's tolerance in codes and "
                      "the fraction of pixels that may differ\n");
      return 2;
    }
    argc -= 2;
    argv += 2;
  }
  if (argc >= 2 && strcmp(argv[1], "--recode") == 0) {
    for (int k = 2; k < argc; k++) {
      Picture p;
      if (!image_load(argv[k], &p.w, &p.h, &p.rgb) || !image_save_kept(argv[k], p.w, p.h, p.rgb))
        return 2;
      free(p.rgb);
    }
    return 0;
  }
  if (argc == 4 && strcmp(argv[1], "--put") == 0)
    return put(argv[2], argv[3]);
  if (argc != 3) {
    fprintf(stderr, "usage: imgcmp [--edge N,T,F] A B | [--edge N,T,F] --put KEPT NEW | --recode FILE...\n");
    return 2;
  }
  Picture a, b;
  if (!image_load(argv[1], &a.w, &a.h, &a.rgb) || !image_load(argv[2], &b.w, &b.h, &b.rgb))
    return 2;
  if (a.w != b.w || a.h != b.h) {
    printf("%s is %dx%d, %s is %dx%d\n", argv[1], a.w, a.h, argv[2], b.w, b.h);
    return 2;
  }
  long max_codes, pixels = differ(&a, &b, &max_codes);
  double block;
  bool same = agree(&a, &b, pixels, &block);
  free(a.rgb);
  free(b.rgb);
  if (pixels == 0)
    return 0;
  printf("%ld of %ld pixels differ, by up to %ld code%s", pixels, (long)a.w * a.h, max_codes,
         max_codes == 1 ? "" : "s");
  if (edge_n > 0)
    printf(" (allowed %.0f); %dx%d block means by up to %.1f codes (allowed %g)",
           edge_f * a.w * a.h, edge_n, edge_n, block, edge_t);
  printf("\n");
  return same ? 0 : 1;
}
