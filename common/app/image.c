/* Image files and comparison (step 01): tone map names, atomic writes
 * (temporary file, then rename) with every byte from film_to_byte, PFM by
 * hand, PNG through libpng and zlib (in bands shared among the threads),
 * JPG/HDR and loading through stb. docs/01-film.md. */
#include "app/image.h"

#include "film.h"
#include "app/outfile.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <png.h>
#include <zlib.h>
#include <stb_image.h>
#include <stb_image_write.h>

bool image_tonemap_parse(const char *name, Tonemap *out)
{
  static const char *const names[] = {"clamp", "srgb", "reinhard"};
  for (int k = 0; k < 3; k++) {
    if (strcmp(name, names[k]) == 0) {
      *out = (Tonemap)k;
      return true;
    }
  }
  return false;
}

/* stb's write callback: a failed write is remembered with its reason. */
static void out_write(void *ctx, void *data, int size)
{
  OutFile *out = ctx;
  if (!out->failed && fwrite(data, 1, (size_t)size, out->f) != (size_t)size) {
    out->failed = true;
    out->err = errno;
  }
}

static const char *extension(const char *path)
{
  const char *dot = strrchr(path, '.');
  const char *slash = strrchr(path, '/');
  return (dot && (!slash || dot > slash)) ? dot + 1 : "";
}

/* The picture to convert to bytes: linear floats, bottom row first. */
typedef struct Bytes {
  int w, h;
  const float *rgb;
  Tonemap tm;
} Bytes;

/* Row j of the upright picture (top row first), tone mapped to bytes. */
static void bytes_row(const Bytes *b, int j, unsigned char *out)
{
  const float *row = b->rgb + (size_t)(b->h - 1 - j) * b->w * 3;
  for (int k = 0; k < b->w * 3; k++)
    out[k] = film_to_byte(row[k], b->tm);
}

/* All the bytes of the picture, upright. */
static unsigned char *to_bytes(int w, int h, const float *rgb, Tonemap tm)
{
  unsigned char *px = malloc((size_t)w * h * 3);
  Bytes b = {w, h, rgb, tm};
  for (int j = 0; px && j < h; j++)
    bytes_row(&b, j, px + (size_t)j * w * 3);
  return px;
}

/* PFM: header, then little-endian floats, bottom row first (the film's own
 * order). A negative scale says little-endian. The body goes out in blocks
 * of 64 KB converted in one buffer on the stack: a write per float cost more
 * than rendering a small picture, and a buffer for the whole body (5.8 MB at
 * 800x600) cost about 1 400 page faults. */
static bool write_pfm(OutFile *out, int w, int h, const float *rgb)
{
  enum { BLOCK = 1 << 14 }; /* floats */
  char head[64];
  int n = snprintf(head, sizeof head, "PF\n%d %d\n-1.0\n", w, h);
  out_write(out, head, n);
  size_t count = (size_t)w * h * 3;
  unsigned char le[4 * BLOCK];
  for (size_t first = 0; first < count; first += BLOCK) {
    size_t len = count - first < BLOCK ? count - first : BLOCK;
    for (size_t k = 0; k < len; k++) {
      uint32_t bits;
      memcpy(&bits, &rgb[first + k], 4);
      for (int byte = 0; byte < 4; byte++)
        le[4 * k + byte] = (unsigned char)(bits >> (8 * byte));
    }
    out_write(out, le, (int)(4 * len));
  }
  return true;
}

/* PNG pixel data in bands of rows, each compressed on its own by one thread,
 * then written in order as the IDAT chunks of one zlib stream: the zlib
 * header before the first band, each band a raw deflate stream (level 1)
 * ended by a sync flush (the last by the final block), the Adler-32 of all
 * the filtered rows after the last (adler32_combine joins the bands'). A
 * band restarts deflate's dictionary, so it is made at least 64 KB, twice
 * the window; the bands depend on the picture's size alone, so the file is
 * the same byte for byte whatever the number of threads. Rows use the Sub
 * filter. libpng writes the signature, IHDR and the chunks' CRCs.
 * docs/performance.md, "PNG in bands". */
enum { BAND_MIN_BYTES = 1 << 16 };

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
static void band_encode(const Bytes *b, int j0, int j1, bool first, bool last, Band *band)
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
    bytes_row(b, j, row);
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

/* libpng's errors come back as a longjmp to png_chunks, without libpng's own
 * "libpng error: ..." line: image_save says what failed and why. */
static void png_quiet_error(png_structp png, png_const_charp message)
{
  (void)message;
  png_longjmp(png, 1);
}

static void png_quiet_warning(png_structp png, png_const_charp message)
{
  (void)png;
  (void)message;
}

/* Signature, IHDR, the bands as IDAT chunks and IEND through libpng (errors
 * arrive by longjmp, hence the helper that owns the setjmp). */
static bool png_chunks(png_structp png, png_infop info, const Bytes *b, const Band *band,
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

static bool write_png(OutFile *out, const Bytes *b)
{
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
    png_init_io(png, out->f);
    ok = png_chunks(png, info, b, band, bands);
  }
  png_destroy_write_struct(&png, &info);
  for (int k = 0; k < bands; k++)
    free(band[k].z);
  free(band);
  return ok;
}

/* Encode into `out`; false when the format is unknown or memory is short. */
static bool encode(OutFile *out, const char *ext, int w, int h, const float *rgb,
                   Tonemap tm)
{
  if (strcmp(ext, "pfm") == 0)
    return write_pfm(out, w, h, rgb);
  if (strcmp(ext, "hdr") == 0) {
    float *up = malloc((size_t)w * h * 3 * sizeof *up);
    if (!up)
      return false;
    for (int j = 0; j < h; j++)
      memcpy(up + (size_t)j * w * 3, rgb + (size_t)(h - 1 - j) * w * 3,
             (size_t)w * 3 * sizeof *up);
    int ok = stbi_write_hdr_to_func(out_write, out, w, h, 3, up);
    free(up);
    return ok != 0;
  }
  if (strcmp(ext, "png") == 0)
    return write_png(out, &(Bytes){w, h, rgb, tm});
  unsigned char *px = to_bytes(w, h, rgb, tm);
  if (!px)
    return false;
  int ok = stbi_write_jpg_to_func(out_write, out, w, h, 3, px, 95);
  free(px);
  return ok != 0;
}

bool image_format_known(const char *path)
{
  static const char *const known[] = {"png", "jpg", "jpeg", "hdr", "pfm"};
  const char *ext = extension(path);
  for (int k = 0; k < 5; k++)
    if (strcmp(ext, known[k]) == 0)
      return true;
  if (*ext)
    fprintf(stderr, "image: cannot write '%s': unknown extension '.%s' "
                    "(expected .png, .jpg, .hdr or .pfm)\n", path, ext);
  else
    fprintf(stderr, "image: cannot write '%s': no extension "
                    "(expected .png, .jpg, .hdr or .pfm)\n", path);
  return false;
}

bool image_save(const char *path, int w, int h, const float *rgb, Tonemap tm)
{
  OutFile out;
  if (!image_format_known(path) || !outfile_open(&out, path))
    return false;
  errno = 0;
  bool ok = encode(&out, extension(path), w, h, rgb, tm);
  if (!ok && !out.err)
    out.err = errno ? errno : ENOMEM;
  return outfile_close(&out, ok);
}

/* Read a PFM (either endianness, 1 or 3 channels) into RGB floats. */
static bool load_pfm(FILE *f, const char *path, int *w, int *h, float **rgb)
{
  char kind[3] = {0};
  float scale;
  if (fscanf(f, "%2s %d %d %f", kind, w, h, &scale) != 4 || fgetc(f) == EOF ||
      (strcmp(kind, "PF") != 0 && strcmp(kind, "Pf") != 0) || *w <= 0 || *h <= 0 ||
      (long long)*w * *h > (1ll << 28) || scale == 0.0f) {
    fprintf(stderr, "image: '%s' is not a PFM file\n", path);
    return false;
  }
  int ch = kind[1] == 'F' ? 3 : 1;
  size_t n = (size_t)*w * *h;
  float *px = malloc(n * 3 * sizeof *px);
  unsigned char *raw = malloc(n * ch * 4);
  bool ok = px && raw && fread(raw, 4, n * ch, f) == n * ch;
  for (size_t k = 0; ok && k < n * 3; k++) {
    const unsigned char *b = raw + 4 * (ch == 3 ? k : k / 3);
    uint32_t bits = scale < 0 ? (uint32_t)b[0] | b[1] << 8 | b[2] << 16 | (uint32_t)b[3] << 24
                              : (uint32_t)b[3] | b[2] << 8 | b[1] << 16 | (uint32_t)b[0] << 24;
    memcpy(&px[k], &bits, 4);
  }
  free(raw);
  if (!ok) {
    fprintf(stderr, "image: '%s' is truncated\n", path);
    free(px);
    return false;
  }
  *rgb = px;
  return true;
}

bool image_load(const char *path, int *w, int *h, float **rgb)
{
  FILE *f = fopen(path, "rb");
  if (!f) {
    fprintf(stderr, "image: cannot read '%s': %s\n", path, strerror(errno));
    return false;
  }
  bool ok;
  if (strcmp(extension(path), "pfm") == 0) {
    ok = load_pfm(f, path, w, h, rgb);
  } else {
    int n;
    unsigned char *px = stbi_load_from_file(f, w, h, &n, 3);
    ok = px != NULL;
    if (!ok)
      fprintf(stderr, "image: cannot read '%s': %s\n", path, stbi_failure_reason());
    else if (!(*rgb = malloc((size_t)*w * *h * 3 * sizeof **rgb)))
      ok = false;
    for (int j = 0; ok && j < *h; j++) /* flip to the film's bottom-up rows */
      for (int k = 0; k < *w * 3; k++)
        (*rgb)[(size_t)j * *w * 3 + k] = px[(size_t)(*h - 1 - j) * *w * 3 + k] / 255.0f;
    stbi_image_free(px);
  }
  fclose(f);
  return ok;
}

ImageDiff image_compare(int w, int h, const float *a, const float *b, float tol)
{
  ImageDiff d = {0.0, 0.0f, 0};
  size_t n = (size_t)w * h * 3;
  for (size_t k = 0; k < n; k++) {
    float e = fabsf(a[k] - b[k]);
    if (!(e <= tol)) /* NaN counts as over */
      d.over++;
    if (e > d.max_abs || e != e)
      d.max_abs = e;
    d.rmse += (double)e * e;
  }
  d.rmse = n ? sqrt(d.rmse / (double)n) : 0.0;
  return d;
}

bool image_save_diff(const char *path, int w, int h, const float *a,
                     const float *b, float tol, float gain)
{
  float *px = malloc((size_t)w * h * 3 * sizeof *px);
  if (!px)
    return false;
  for (size_t p = 0; p < (size_t)w * h; p++) {
    float e = 0.0f;
    for (int c = 0; c < 3; c++)
      e = fmaxf(e, fabsf(a[3 * p + c] - b[3 * p + c]));
    bool over = !(e <= tol);
    px[3 * p + 0] = over ? 1.0f : gain * e;
    px[3 * p + 1] = over ? 0.0f : gain * e;
    px[3 * p + 2] = over ? 0.0f : gain * e;
  }
  bool ok = image_save(path, w, h, px, TONEMAP_CLAMP);
  free(px);
  return ok;
}
