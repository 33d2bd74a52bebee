/* Compare two images pixel by pixel, as decoded bytes (not file bytes: two
 * PNG encoders may compress the same pixels differently). For make
 * check-images (tools/images.sh). Usage: imgcmp A B; exit 0 when every
 * channel is equal, 1 when some differ (one line says how), 2 when a file
 * cannot be read or the sizes differ. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "app/image.h"

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: imgcmp A B\n");
    return 2;
  }
  int wa, ha, wb, hb;
  float *a, *b;
  if (!image_load(argv[1], &wa, &ha, &a))
    return 2;
  if (!image_load(argv[2], &wb, &hb, &b))
    return 2;
  if (wa != wb || ha != hb) {
    printf("%s is %dx%d, %s is %dx%d\n", argv[1], wa, ha, argv[2], wb, hb);
    return 2;
  }
  long pixels = 0, max_codes = 0;
  for (long p = 0; p < (long)wa * ha; p++) {
    long worst = 0;
    for (int c = 0; c < 3; c++) {
      long codes = labs(lroundf(255.0f * a[3 * p + c]) - lroundf(255.0f * b[3 * p + c]));
      worst = codes > worst ? codes : worst;
    }
    pixels += worst > 0;
    max_codes = worst > max_codes ? worst : max_codes;
  }
  free(a);
  free(b);
  if (pixels == 0)
    return 0;
  printf("%ld of %ld pixels differ, by up to %ld code%s\n", pixels, (long)wa * ha, max_codes,
         max_codes == 1 ? "" : "s");
  return 1;
}
