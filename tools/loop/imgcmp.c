/* Compare two images pixel by pixel, as decoded bytes (not file bytes: two
 * PNG encoders may compress the same pixels differently), and write the
 * pictures the repository keeps (make regen, make check-derived;
 * tools/figures/images.sh, tools/figures/docimg.sh).
 *   imgcmp A B           exit 0 when every channel is equal, 1 when some
 *                        differ (one line says how), 2 when a file cannot be
 *                        read or the sizes differ
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
    if (pixels == 0) {
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
    fprintf(stderr, "usage: imgcmp A B | --put KEPT NEW | --recode FILE...\n");
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
  free(a.rgb);
  free(b.rgb);
  if (pixels == 0)
    return 0;
  printf("%ld of %ld pixels differ, by up to %ld code%s\n", pixels, (long)a.w * a.h, max_codes,
         max_codes == 1 ? "" : "s");
  return 1;
}
