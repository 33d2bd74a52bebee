/* Image files and comparison (step 01): tone map names, atomic writes
 * (temporary file, then rename) with every byte from film_to_byte, PFM by
 * hand, PNG through libpng (or the speed pack's, app/pack.h),
 * JPG/HDR and loading through stb. docs/01-film.md. */
#include "app/image.h"

#include "film.h"
#include "app/outfile.h"
#include "app/pack.h"
#include "app/png_quiet.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <png.h>
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
 * of 64 KB converted in one buffer on the stack: a write per float costs
 * more than rendering a small picture, and a buffer for the whole body
 * costs a page fault per 4 KB. */
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

/* The picture through libpng, row by row, each row filtered by Sub and
 * deflated at level 1 (fast; a picture is written once). Errors arrive by
 * longjmp, hence the helper that owns the setjmp; `row` is its buffer. */
static bool png_rows(png_structp png, png_infop info, const Bytes *b, unsigned char *row)
{
  if (setjmp(png_jmpbuf(png)))
    return false;
  png_set_IHDR(png, info, (png_uint_32)b->w, (png_uint_32)b->h, 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, 1);
  png_write_info(png, info);
  for (int j = 0; j < b->h; j++) {
    bytes_row(b, j, row);
    png_write_row(png, row);
  }
  png_write_end(png, info);
  return true;
}

static bool write_png(OutFile *out, const Bytes *b)
{
  unsigned char *row = malloc((size_t)b->w * 3);
  png_structp png = row ? png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL,
                                                  png_quiet_error, png_quiet_warning)
                        : NULL;
  png_infop info = png ? png_create_info_struct(png) : NULL;
  bool ok = png && info;
  if (ok) {
    png_init_io(png, out->f);
    ok = png_rows(png, info, b, row);
  }
  png_destroy_write_struct(&png, &info);
  free(row);
  return ok;
}

/* Row j of the picture a Bytes points to (pack_png's row function). */
static void picture_row(const void *picture, int j, unsigned char *out)
{
  bytes_row(picture, j, out);
}

/* Encode into `out`; false when the format is unknown or memory is short.
 * `plain`: a .png through libpng, never the speed pack's writer. */
static bool encode(OutFile *out, const char *ext, int w, int h, const float *rgb,
                   Tonemap tm, bool plain)
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
  if (strcmp(ext, "png") == 0) {
    Bytes b = {w, h, rgb, tm};
    int packed = plain ? -1 : pack_png(out->f, w, h, picture_row, &b); /* in parallel */
    return packed >= 0 ? packed == 1 : write_png(out, &b);
  }
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

static bool save(const char *path, int w, int h, const float *rgb, Tonemap tm, bool plain)
{
  OutFile out;
  if (!image_format_known(path) || !outfile_open(&out, path))
    return false;
  errno = 0;
  bool ok = encode(&out, extension(path), w, h, rgb, tm, plain);
  if (!ok && !out.err)
    out.err = errno ? errno : ENOMEM;
  return outfile_close(&out, ok);
}

bool image_save(const char *path, int w, int h, const float *rgb, Tonemap tm)
{
  return save(path, w, h, rgb, tm, false);
}

bool image_save_kept(const char *path, int w, int h, const float *rgb)
{
  if (strcmp(extension(path), "png") != 0) {
    fprintf(stderr, "image: '%s': a kept picture is a .png\n", path);
    return false;
  }
  return save(path, w, h, rgb, TONEMAP_CLAMP, true);
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
