/* PNG encoder: every row with the Sub filter, streamed row by row into one
 * zlib stream at level 1, in one IDAT chunk. docs/performance.md compares it with stb's encoder. */
#include "png.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

/* Filter byte 1 (Sub), then each byte minus the same channel of the pixel to
 * its left (mod 256). On smooth renders this turns most bytes into small
 * values that compress well; trying all five filters per row, as stb does,
 * costs more than it saves at level 1. */
static void filter_sub(unsigned char *out, const unsigned char *in, size_t row)
{
  out[0] = 1;
  for (size_t k = 0; k < row; k++)
    out[1 + k] = (unsigned char)(in[k] - (k >= 3 ? in[k - 3] : 0));
}

static void put32(unsigned char *p, uint32_t v)
{
  p[0] = (unsigned char)(v >> 24);
  p[1] = (unsigned char)(v >> 16);
  p[2] = (unsigned char)(v >> 8);
  p[3] = (unsigned char)v;
}

/* One chunk: length, type, data, CRC-32 of type and data. */
static void chunk(PngWriteFn *write, void *ctx, const char *type,
                  unsigned char *data, uint32_t len)
{
  unsigned char head[8], tail[4];
  put32(head, len);
  memcpy(head + 4, type, 4);
  uLong crc = crc32(crc32(0L, Z_NULL, 0), head + 4, 4);
  if (len > 0)
    crc = crc32(crc, data, len);
  put32(tail, (uint32_t)crc);
  write(ctx, head, 8);
  if (len > 0)
    write(ctx, data, (int)len);
  write(ctx, tail, 4);
}

/* Filter and deflate the rows one at a time (no filtered copy of the whole
 * picture) into a new buffer; its size in *out_len. NULL on failure. */
static unsigned char *deflate_rows(int w, int h, const unsigned char *rgb, size_t *out_len)
{
  size_t row = (size_t)w * 3;
  uLong cap = compressBound((uLong)((row + 1) * (size_t)h));
  unsigned char *out = malloc(cap), *line = malloc(row + 1);
  z_stream z = {0};
  bool ok = out && line && deflateInit(&z, 1) == Z_OK;
  z.next_out = out;
  z.avail_out = (uInt)cap;
  for (int j = 0; ok && j < h; j++) {
    filter_sub(line, rgb + (size_t)j * row, row);
    z.next_in = line;
    z.avail_in = (uInt)(row + 1);
    int rc = deflate(&z, j == h - 1 ? Z_FINISH : Z_NO_FLUSH);
    ok = j == h - 1 ? rc == Z_STREAM_END : rc == Z_OK;
  }
  *out_len = z.total_out;
  deflateEnd(&z);
  free(line);
  if (!ok) {
    free(out);
    return NULL;
  }
  return out;
}

bool png_encode(PngWriteFn *write, void *ctx, int w, int h, const unsigned char *rgb)
{
  static const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  size_t zlen = 0;
  if (((size_t)w * 3 + 1) * (size_t)h > 0x7fffffffu) /* one IDAT, zlib's uInt */
    return false;
  unsigned char *z = w > 0 && h > 0 ? deflate_rows(w, h, rgb, &zlen) : NULL;
  if (!z)
    return false;
  /* IHDR: size, 8 bits per channel, colour type 2 (RGB), deflate, adaptive
   * filters, no interlace. */
  unsigned char ihdr[13] = {0, 0, 0, 0, 0, 0, 0, 0, 8, 2, 0, 0, 0};
  put32(ihdr, (uint32_t)w);
  put32(ihdr + 4, (uint32_t)h);
  write(ctx, (void *)signature, 8);
  chunk(write, ctx, "IHDR", ihdr, 13);
  chunk(write, ctx, "IDAT", z, (uint32_t)zlen);
  chunk(write, ctx, "IEND", NULL, 0);
  free(z);
  return true;
}
