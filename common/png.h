/* PNG encoder (step 01's export, made fast): 8-bit RGB rows compressed with
 * zlib at its fastest level, the two halves of the picture at once. Replaces
 * stb's encoder, which spent longer writing the picture than rendering it.
 * docs/performance.md. */
#ifndef RT_PNG_H
#define RT_PNG_H

#include <stdbool.h>

/* Receives the file's bytes in order (the same shape as stb's write callback). */
typedef void PngWriteFn(void *ctx, void *data, int size);

/* Writes the 3 w bytes of row j (j = 0 is the top row) into `rgb`. Called
 * from two threads at once, for different rows. */
typedef void PngRowFn(void *ctx, int j, unsigned char *rgb);

/* Encode a w x h RGB picture, its rows given by `row`, as a PNG and pass the
 * file to `write`. The bytes depend only on the pixels. False when memory is
 * short or zlib fails. */
bool png_encode(PngWriteFn *write, void *write_ctx, int w, int h, PngRowFn *row,
                void *row_ctx);

#endif
