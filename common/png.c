/* PNG encoder: every row with the Sub filter, then one zlib stream at level 1
 * in one IDAT chunk. docs/performance.md compares it with stb's encoder. */
#include "png.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

/* Filter byte 1 (Sub), then each byte minus the same channel of the pixel to
 * its left (mod 256). On smooth renders this turns most bytes into small
 * values that compress well; trying all five filters per row, as stb does,
 * costs more than it saves at level 1. */
static void filter_sub(unsigned char *out, int w, int h, const unsigned char *rgb)
{
  size_t row = (size_t)w * 3;
  for (int j = 0; j < h; j++) {
    const unsigned char *in = rgb + (size_t)j * row;
    unsigned char *o = out + (size_t)j * (row + 1);
    o[0] = 1;
    for (size_t k = 0; k < row; k++)
      o[1 + k] = (unsigned char)(in[k] - (k >= 3 ? in[k - 3] : 0));
  }
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

/* Deflate `in` into a new buffer; its size in *out_len. NULL on failure. */
static unsigned char *deflate_fast(const unsigned char *in, size_t len, size_t *out_len)
{
  uLong cap = compressBound((uLong)len);
  unsigned char *out = malloc(cap);
  z_stream z = {0};
  if (!out || deflateInit(&z, 1) != Z_OK) {
    free(out);
    return NULL;
  }
  z.next_in = (Bytef *)in;
  z.avail_in = (uInt)len;
  z.next_out = out;
  z.avail_out = (uInt)cap;
  int rc = deflate(&z, Z_FINISH);
  *out_len = z.total_out;
  deflateEnd(&z);
  if (rc != Z_STREAM_END) {
    free(out);
    return NULL;
  }
  return out;
}

bool png_encode(PngWriteFn *write, void *ctx, int w, int h, const unsigned char *rgb)
{
  static const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  size_t len = ((size_t)w * 3 + 1) * (size_t)h, zlen = 0;
  if (len > 0x7fffffffu) /* one IDAT chunk and zlib's uInt counts */
    return false;
  unsigned char *filtered = malloc(len);
  if (!filtered)
    return false;
  filter_sub(filtered, w, h, rgb);
  unsigned char *z = deflate_fast(filtered, len, &zlen);
  free(filtered);
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
