/* PNG encoder: every row with the Sub filter, deflated at zlib's level 1. The
 * top and bottom halves are made and compressed by two threads as two raw
 * deflate streams, joined into one zlib stream (the way pigz does it: the
 * first half ends on a byte boundary without the final-block bit, the
 * checksums are combined), in one IDAT chunk. docs/performance.md. */
#include "png.h"

#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

/* One half of the picture: rows [j0, j1), its raw deflate stream and the
 * Adler-32 of the filtered bytes it holds. */
typedef struct Part {
  int w, j0, j1;
  bool last; /* ends the stream */
  PngRowFn *row;
  void *row_ctx;
  unsigned char *z;
  size_t z_len, raw_len;
  uLong adler;
  bool ok;
} Part;

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

/* Make, filter and deflate the part's rows one at a time. The first half is
 * closed with a full flush (byte-aligned, not final), the last one finished. */
static void *part_deflate(void *arg)
{
  Part *p = arg;
  size_t row = (size_t)p->w * 3;
  p->raw_len = (row + 1) * (size_t)(p->j1 - p->j0);
  uLong cap = compressBound((uLong)p->raw_len) + 16;
  unsigned char *px = malloc(2 * row + 1), *line = px + row;
  z_stream z = {0};
  p->z = malloc(cap);
  p->adler = adler32(0L, Z_NULL, 0);
  bool started = px && p->z &&
                 deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) == Z_OK;
  p->ok = started;
  z.next_out = p->z;
  z.avail_out = (uInt)cap;
  for (int j = p->j0; p->ok && j < p->j1; j++) {
    p->row(p->row_ctx, j, px);
    filter_sub(line, px, row);
    p->adler = adler32(p->adler, line, (uInt)(row + 1));
    z.next_in = line;
    z.avail_in = (uInt)(row + 1);
    int flush = j < p->j1 - 1 ? Z_NO_FLUSH : p->last ? Z_FINISH : Z_FULL_FLUSH;
    int rc = deflate(&z, flush);
    p->ok = flush == Z_FINISH ? rc == Z_STREAM_END : rc == Z_OK && z.avail_out > 0;
  }
  p->z_len = z.total_out;
  if (started)
    deflateEnd(&z);
  free(px);
  return NULL;
}

static void put32(unsigned char *p, uint32_t v)
{
  p[0] = (unsigned char)(v >> 24);
  p[1] = (unsigned char)(v >> 16);
  p[2] = (unsigned char)(v >> 8);
  p[3] = (unsigned char)v;
}

/* One chunk: length, type, data (given in `n` pieces), CRC-32 of type and data. */
static void chunk(PngWriteFn *write, void *ctx, const char *type, int n,
                  unsigned char *const data[], const size_t len[])
{
  unsigned char head[8], tail[4];
  size_t total = 0;
  for (int k = 0; k < n; k++)
    total += len[k];
  put32(head, (uint32_t)total);
  memcpy(head + 4, type, 4);
  uLong crc = crc32(crc32(0L, Z_NULL, 0), head + 4, 4);
  for (int k = 0; k < n; k++)
    crc = crc32(crc, data[k], (uInt)len[k]);
  put32(tail, (uint32_t)crc);
  write(ctx, head, 8);
  for (int k = 0; k < n; k++)
    if (len[k] > 0)
      write(ctx, data[k], (int)len[k]);
  write(ctx, tail, 4);
}

/* Both halves, the second in a thread of its own (or here, if none starts). */
static bool deflate_halves(Part part[2])
{
  pthread_t id;
  bool threaded = pthread_create(&id, NULL, part_deflate, &part[1]) == 0;
  part_deflate(&part[0]);
  if (threaded)
    pthread_join(id, NULL);
  else
    part_deflate(&part[1]);
  return part[0].ok && part[1].ok;
}

bool png_encode(PngWriteFn *write, void *write_ctx, int w, int h, PngRowFn *row,
                void *row_ctx)
{
  static const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (w <= 0 || h <= 0 || ((size_t)w * 3 + 1) * (size_t)h > 0x7fffffffu)
    return false; /* one IDAT chunk, zlib's uInt counts */
  Part part[2] = {{.w = w, .j0 = 0, .j1 = h / 2, .row = row, .row_ctx = row_ctx},
                  {.w = w, .j0 = h / 2, .j1 = h, .last = true, .row = row, .row_ctx = row_ctx}};
  bool ok = deflate_halves(part);
  if (ok) {
    /* IHDR: size, 8 bits per channel, colour type 2 (RGB), deflate, adaptive
     * filters, no interlace. The zlib stream: header 78 01 (32 KB window,
     * fastest level), the two halves, Adler-32 of all the filtered bytes. */
    unsigned char ihdr[13] = {0, 0, 0, 0, 0, 0, 0, 0, 8, 2, 0, 0, 0}, zhead[2] = {0x78, 0x01};
    unsigned char ztail[4];
    put32(ihdr, (uint32_t)w);
    put32(ihdr + 4, (uint32_t)h);
    put32(ztail, (uint32_t)adler32_combine(part[0].adler, part[1].adler,
                                           (z_off_t)part[1].raw_len));
    write(write_ctx, (void *)signature, 8);
    chunk(write, write_ctx, "IHDR", 1, (unsigned char *[]){ihdr}, (size_t[]){13});
    chunk(write, write_ctx, "IDAT", 4,
          (unsigned char *[]){zhead, part[0].z, part[1].z, ztail},
          (size_t[]){2, part[0].z_len, part[1].z_len, 4});
    chunk(write, write_ctx, "IEND", 0, NULL, NULL);
  }
  free(part[0].z);
  free(part[1].z);
  return ok;
}
