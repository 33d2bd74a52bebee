/* PNG encoder (step 01's export, made fast): 8-bit RGB rows compressed with
 * zlib at its fastest level. Replaces stb's encoder, which spent longer
 * writing the picture than rendering it. docs/performance.md. */
#ifndef RT_PNG_H
#define RT_PNG_H

#include <stdbool.h>

/* Receives the file's bytes in order (the same shape as stb's write callback). */
typedef void PngWriteFn(void *ctx, void *data, int size);

/* Encode w x h RGB bytes (top row first, 3 w bytes per row) as a PNG and pass
 * it to `write`. False when memory is short or zlib fails. */
bool png_encode(PngWriteFn *write, void *ctx, int w, int h, const unsigned char *rgb);

#endif
