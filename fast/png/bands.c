/* PNG written in bands of rows compressed at once (png/bands.h). */
#include "png/bands.h"
#include "app/png_quiet.h"

#include <stdbool.h>
#include <stdlib.h>

#include <png.h>
#include <zlib.h>

/* PNG pixel data in bands of rows, each compressed on its own by one thread,
 * then written in order as the IDAT chunks of one zlib stream: the zlib
 * header before the first band, each band a raw deflate stream (level 1)
 * ended by a sync flush (the last by the final block), the Adler-32 of all
 * the filtered rows after the last (adler32_combine joins the bands'). A
 * band restarts deflate's dictionary, so it is made at least 64 KB, twice
 * the window; the bands depend on the picture's size alone, so the file is
 * the same byte for byte whatever the number of threads. Rows use the Sub
 * filter. libpng writes the signature, IHDR and the chunks' CRCs.
 * docs/performance.md. */
enum { BAND_MIN_BYTES = 1 << 16 };

/* The picture to write: w x h, row j (top row first) from row(rows, j, out). */
typedef struct Picture {
  int w, h;
  PackRowFn row;
  const void *rows;
} Picture;

typedef struct Band {
  unsigned char *z; /* compressed bytes, with room for the zlib header (the
                       first band) and the Adler-32 (the last) */
  size_t len;       /* bytes of z written */
  uLong adler;      /* of this band's filtered rows */
  size_t raw;       /* filtered bytes */
  bool ok;
} Band;

/* Rows [j0, j1) of the upright picture, tone mapped, filtered and
 * compressed into *band: after the zlib header when `first`, ended by the
 * final block when `last`. */
static void band_encode(const Picture *b, int j0, int j1, bool first, bool last, Band *band)
{
  size_t stride = 1 + (size_t)b->w * 3;
  band->raw = (size_t)(j1 - j0) * stride;
  unsigned char *f = malloc(band->raw), *row = malloc(stride);
  z_stream z = {0};
  band->ok = f && row && deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) == Z_OK;
  size_t room = band->ok ? deflateBound(&z, (uLong)band->raw) + 16 : 0;
  band->z = band->ok ? malloc(room + 6) : NULL;
  band->ok = band->ok && band->z;
  for (int j = j0; band->ok && j < j1; j++) {
    unsigned char *out = f + (size_t)(j - j0) * stride;
    b->row(b->rows, j, row);
    out[0] = 1; /* Sub: each byte minus the one a pixel before, modulo 256 */
    for (size_t k = 0; k < stride - 1; k++)
      out[1 + k] = (unsigned char)(row[k] - (k >= 3 ? row[k - 3] : 0));
  }
  if (band->ok) {
    size_t at = first ? 2 : 0;
    if (first) {
      band->z[0] = 0x78; /* deflate, 32 KB window; 0x7801 % 31 == 0 */
      band->z[1] = 0x01;
    }
    z.next_in = f;
    z.avail_in = (uInt)band->raw;
    z.next_out = band->z + at;
    z.avail_out = (uInt)room;
    band->ok = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH) == (last ? Z_STREAM_END : Z_OK) &&
               z.avail_in == 0;
    band->len = at + (room - z.avail_out);
    band->adler = adler32(adler32(0L, Z_NULL, 0), f, (uInt)band->raw);
  }
  if (z.state) /* set by deflateInit2 */
    deflateEnd(&z);
  free(f);
  free(row);
}

/* Signature, IHDR, the bands as IDAT chunks and IEND through libpng (errors
 * arrive by longjmp, hence the helper that owns the setjmp). */
static bool png_chunks(png_structp png, png_infop info, const Picture *b, const Band *band,
                       int bands)
{
  if (setjmp(png_jmpbuf(png)))
    return false;
  png_set_IHDR(png, info, (png_uint_32)b->w, (png_uint_32)b->h, 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int k = 0; k < bands; k++)
    png_write_chunk(png, (png_const_bytep) "IDAT", band[k].z, band[k].len);
  png_write_chunk(png, (png_const_bytep) "IEND", NULL, 0);
  return true;
}

bool bands_write_png(FILE *f, int w, int h, PackRowFn row, const void *picture)
{
  const Picture *b = &(Picture){w, h, row, picture};
  size_t stride = 1 + (size_t)b->w * 3;
  int rows = (int)((BAND_MIN_BYTES + stride - 1) / stride);
  int bands = (b->h + rows - 1) / rows;
  Band *band = calloc((size_t)bands, sizeof *band);
  if (!band)
    return false;
  bool ok = true;
#pragma omp parallel for schedule(dynamic, 1) reduction(&& : ok) if (bands > 1)
  for (int k = 0; k < bands; k++) {
    int j1 = (k + 1) * rows < b->h ? (k + 1) * rows : b->h;
    band_encode(b, k * rows, j1, k == 0, k == bands - 1, &band[k]);
    ok = ok && band[k].ok;
  }
  if (ok) { /* the stream's Adler-32, big-endian, after the last band */
    uLong adler = band[0].adler;
    for (int k = 1; k < bands; k++)
      adler = adler32_combine(adler, band[k].adler, (z_off_t)band[k].raw);
    Band *last = &band[bands - 1];
    for (int k = 0; k < 4; k++)
      last->z[last->len++] = (unsigned char)(adler >> (24 - 8 * k));
  }
  png_structp png = ok ? png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL,
                                                 png_quiet_error, png_quiet_warning)
                       : NULL;
  png_infop info = png ? png_create_info_struct(png) : NULL;
  ok = ok && png && info;
  if (ok) {
    png_init_io(png, f);
    ok = png_chunks(png, info, b, band, bands);
  }
  png_destroy_write_struct(&png, &info);
  for (int k = 0; k < bands; k++)
    free(band[k].z);
  free(band);
  return ok;
}
