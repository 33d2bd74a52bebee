/* PNG in bands of rows, each compressed on its own by one thread, then
 * written in order as the IDAT chunks of one zlib stream (pack_png,
 * app/pack.h). The file is the same byte for byte whatever the number of
 * threads. */
#ifndef RT_BANDS_H
#define RT_BANDS_H

#include <stdbool.h>
#include <stdio.h>

#include "app/pack.h"

/* Write the PNG of the w x h picture whose rows `row` gives to f; false
 * when it failed (errno, or out of memory). */
bool bands_write_png(FILE *f, int w, int h, PackRowFn row, const void *picture);

#endif
