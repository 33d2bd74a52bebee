/* Unit tests of image export (step 01): an asymmetric "F" picture saved as
 * PNG and PFM and read back (flips and R/B swaps fail), byte rounding, tone
 * maps, atomic writes. docs/01-film.md. */
#include <criterion/criterion.h>
#include <criterion/redirect.h>

#include <dirent.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <stb_image.h>

#include "app/image.h"

#define OUT_DIR BUILD_DIR "/test-out"

/* A red "F" on blue, 5 x 7, written upright (top row first), with a green
 * pixel at the bottom right and a grey one at the top right. */
static const char *const F_ROWS[7] = {
    "RRRRW",
    "RBBBB",
    "RBBBB",
    "RRRBB",
    "RBBBB",
    "RBBBB",
    "RBBBG",
};
enum { F_W = 5, F_H = 7 };

/* The bytes of a letter of F_ROWS. */
static void letter_bytes(char c, unsigned char out[3])
{
  static const struct {
    char c;
    unsigned char rgb[3];
  } table[] = {{'R', {255, 0, 0}}, {'B', {0, 0, 255}}, {'G', {0, 200, 0}},
               {'W', {64, 128, 192}}};
  memset(out, 0, 3);
  for (size_t k = 0; k < sizeof table / sizeof table[0]; k++)
    if (table[k].c == c)
      memcpy(out, table[k].rgb, 3);
}

/* The F as film floats (byte / 255), rows from the bottom. */
static void f_picture(float rgb[F_W * F_H * 3])
{
  for (int j = 0; j < F_H; j++)
    for (int i = 0; i < F_W; i++) {
      unsigned char b[3];
      letter_bytes(F_ROWS[F_H - 1 - j][i], b);
      for (int c = 0; c < 3; c++)
        rgb[(j * F_W + i) * 3 + c] = b[c] / 255.0f;
    }
}

Test(image, png_of_the_f_is_upright_in_the_file_and_reads_back)
{
  float rgb[F_W * F_H * 3];
  f_picture(rgb);
  mkdir(OUT_DIR, 0755);
  const char *path = OUT_DIR "/f.png";
  cr_assert(image_save(path, F_W, F_H, rgb, TONEMAP_CLAMP));

  /* The file itself, read by stb: top row first, R G B order. */
  int w, h, n;
  unsigned char *px = stbi_load(path, &w, &h, &n, 3);
  cr_assert(px && w == F_W && h == F_H);
  for (int row = 0; row < F_H; row++)
    for (int i = 0; i < F_W; i++) {
      unsigned char b[3];
      letter_bytes(F_ROWS[row][i], b);
      cr_expect(memcmp(px + (row * F_W + i) * 3, b, 3) == 0,
                "file row %d (from the top), column %d is %d %d %d, expected '%c'", row, i,
                px[(row * F_W + i) * 3], px[(row * F_W + i) * 3 + 1],
                px[(row * F_W + i) * 3 + 2], F_ROWS[row][i]);
    }
  stbi_image_free(px);

  /* image_load gives the film's rows back, bottom first. */
  float *back;
  cr_assert(image_load(path, &w, &h, &back));
  cr_assert(w == F_W && h == F_H);
  for (int k = 0; k < F_W * F_H * 3; k++)
    cr_expect(back[k] == rgb[k], "float %d (pixel %d, %d): %g, expected %g", k,
              (k / 3) % F_W, (k / 3) / F_W, back[k], rgb[k]);
  free(back);
}

/* Read a little-endian float. */
static float le_float(const unsigned char *b)
{
  uint32_t bits = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
                  (uint32_t)b[3] << 24;
  float f;
  memcpy(&f, &bits, 4);
  return f;
}

Test(image, pfm_of_the_f_has_the_spec_layout_and_reads_back)
{
  float rgb[F_W * F_H * 3];
  f_picture(rgb);
  mkdir(OUT_DIR, 0755);
  const char *path = OUT_DIR "/f.pfm";
  cr_assert(image_save(path, F_W, F_H, rgb, TONEMAP_CLAMP));

  /* PFM: "PF\n5 7\n-1.0\n" (negative scale = little-endian), then the rows
   * from the BOTTOM of the picture: the first pixel is the F's foot (red),
   * the fifth the green one. */
  FILE *f = fopen(path, "rb");
  cr_assert(f);
  unsigned char buf[64 + F_W * F_H * 12];
  size_t got = fread(buf, 1, sizeof buf, f);
  fclose(f);
  const char head[] = "PF\n5 7\n-1.0\n";
  size_t hl = sizeof head - 1;
  cr_assert(got == hl + F_W * F_H * 12, "file has %zu bytes", got);
  cr_assert(memcmp(buf, head, hl) == 0, "header '%.*s'", (int)hl, buf);
  for (int j = 0; j < F_H; j++)
    for (int i = 0; i < F_W; i++) {
      unsigned char b[3];
      letter_bytes(F_ROWS[F_H - 1 - j][i], b);
      for (int c = 0; c < 3; c++)
        cr_expect(le_float(buf + hl + ((j * F_W + i) * 3 + c) * 4) == b[c] / 255.0f,
                  "pixel (%d, %d) channel %d", i, j, c);
    }

  float *back;
  int w, h;
  cr_assert(image_load(path, &w, &h, &back));
  cr_assert(w == F_W && h == F_H);
  cr_expect(memcmp(back, rgb, sizeof rgb) == 0, "PFM round trip changed the floats");
  free(back);
}

Test(image, pfm_round_trip_keeps_every_bit)
{
  /* Values no byte format keeps: HDR, negative, tiny, subnormal, -0, huge. */
  float rgb[2 * 3 * 3] = {1e-30f, 3.4e38f, -2.5f, 0x1p-140f, -0.0f, 1234.5678f,
                          0.1f, 0.2f, 0.3f, 1.0f + 0x1p-23f, 65504.0f, 7.0f,
                          INFINITY, -INFINITY, 0.0f, 1e10f, 3.0f, 0.999999f};
  mkdir(OUT_DIR, 0755);
  const char *path = OUT_DIR "/bits.pfm";
  cr_assert(image_save(path, 3, 2, rgb, TONEMAP_REINHARD));
  float *back;
  int w, h;
  cr_assert(image_load(path, &w, &h, &back));
  cr_assert(w == 3 && h == 2);
  cr_expect(memcmp(back, rgb, sizeof rgb) == 0, "PFM round trip changed some bits");
  free(back);
}

Test(image, byte_rounds_to_nearest_at_every_code)
{
  /* round(255 c): a value 0.02/255 below the midpoint of codes k and k+1
   * gives k, 0.02/255 above gives k+1. */
  for (int k = 0; k < 255; k++) {
    float below = (float)((k + 0.48L) / 255.0L), above = (float)((k + 0.52L) / 255.0L);
    cr_expect(film_to_byte(below, TONEMAP_CLAMP) == k, "(%d + 0.48)/255 -> %d", k,
              film_to_byte(below, TONEMAP_CLAMP));
    cr_expect(film_to_byte(above, TONEMAP_CLAMP) == k + 1, "(%d + 0.52)/255 -> %d", k,
              film_to_byte(above, TONEMAP_CLAMP));
    float exact = (float)k / 255.0f;
    cr_expect(film_to_byte(exact, TONEMAP_CLAMP) == k, "%d/255 -> %d", k,
              film_to_byte(exact, TONEMAP_CLAMP));
  }
}

Test(image, byte_clamps_and_maps_nan_to_zero)
{
  cr_expect(film_to_byte(1.0f, TONEMAP_CLAMP) == 255);
  cr_expect(film_to_byte(0.999f, TONEMAP_CLAMP) == 255); /* 254.745 */
  cr_expect(film_to_byte(0.997f, TONEMAP_CLAMP) == 254); /* 254.235 */
  cr_expect(film_to_byte(1.5f, TONEMAP_CLAMP) == 255);
  cr_expect(film_to_byte(1e30f, TONEMAP_CLAMP) == 255);
  cr_expect(film_to_byte(INFINITY, TONEMAP_CLAMP) == 255);
  cr_expect(film_to_byte(0.0f, TONEMAP_CLAMP) == 0);
  cr_expect(film_to_byte(-0.0f, TONEMAP_CLAMP) == 0);
  cr_expect(film_to_byte(-0.5f, TONEMAP_CLAMP) == 0);
  cr_expect(film_to_byte(-INFINITY, TONEMAP_CLAMP) == 0);
  cr_expect(film_to_byte(NAN, TONEMAP_CLAMP) == 0);
  cr_expect(film_to_byte(NAN, TONEMAP_SRGB) == 0);
  cr_expect(film_to_byte(NAN, TONEMAP_REINHARD) == 0);
  cr_expect(film_to_byte(-1.0f, TONEMAP_SRGB) == 0);
  cr_expect(film_to_byte(-1.0f, TONEMAP_REINHARD) == 0);
}

Test(image, srgb_spot_values_by_hand)
{
  /* 12.92 c below 0.0031308, else 1.055 c^(1/2.4) - 0.055; times 255:
   *   0.002 -> 12.92 * 0.002 * 255                      =   6.589 -> 7
   *   0.18  -> 0.18^(1/2.4) = e^(-1.714798/2.4) = 0.489468,
   *            (1.055 * 0.489468 - 0.055) * 255         = 117.65 -> 118
   *   0.5   -> 0.5^(1/2.4) = 0.749154, (0.790357 - 0.055) * 255 = 187.52 -> 188
   *   1.0 -> 255, 2.0 clamps to 1.0 -> 255. */
  cr_expect_eq(film_to_byte(0.002f, TONEMAP_SRGB), 7);
  cr_expect_eq(film_to_byte(0.18f, TONEMAP_SRGB), 118);
  cr_expect_eq(film_to_byte(0.5f, TONEMAP_SRGB), 188);
  cr_expect_eq(film_to_byte(1.0f, TONEMAP_SRGB), 255);
  cr_expect_eq(film_to_byte(2.0f, TONEMAP_SRGB), 255);
  cr_expect_eq(film_to_byte(0.0f, TONEMAP_SRGB), 0);
}

Test(image, reinhard_spot_values_by_hand)
{
  /* c / (1 + c), then sRGB:
   *   1.0 -> 0.5  -> 188 (above)
   *   3.0 -> 0.75 -> 0.75^(1/2.4) = e^(-0.287682/2.4) = 0.887034,
   *                  (1.055 * 0.887034 - 0.055) * 255 = 224.61 -> 225
   *   0.25 -> 0.2 -> 0.2^(1/2.4) = e^(-1.609438/2.4) = 0.511402,
   *                  (0.539529 - 0.055) * 255 = 123.55 -> 124
   *   huge and infinite values tend to 1 -> 255. */
  cr_expect_eq(film_to_byte(1.0f, TONEMAP_REINHARD), 188);
  cr_expect_eq(film_to_byte(3.0f, TONEMAP_REINHARD), 225);
  cr_expect_eq(film_to_byte(0.25f, TONEMAP_REINHARD), 124);
  cr_expect_eq(film_to_byte(1e30f, TONEMAP_REINHARD), 255);
  cr_expect_eq(film_to_byte(INFINITY, TONEMAP_REINHARD), 255);
}

Test(image, tonemap_names_parse)
{
  Tonemap t;
  cr_expect(image_tonemap_parse("clamp", &t) && t == TONEMAP_CLAMP);
  cr_expect(image_tonemap_parse("srgb", &t) && t == TONEMAP_SRGB);
  cr_expect(image_tonemap_parse("reinhard", &t) && t == TONEMAP_REINHARD);
  cr_expect(!image_tonemap_parse("aces", &t));
  cr_expect(!image_tonemap_parse("", &t));
}

/* The whole content of a file into buf; its length, or -1. */
static long slurp(const char *path, char *buf, size_t size)
{
  FILE *f = fopen(path, "rb");
  if (!f)
    return -1;
  size_t n = fread(buf, 1, size, f);
  fclose(f);
  return (long)n;
}

/* Names in OUT_DIR/dir starting with `prefix`. */
static int count_files(const char *dir, const char *prefix)
{
  DIR *d = opendir(dir);
  int n = 0;
  for (struct dirent *e; d && (e = readdir(d));)
    n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
  if (d)
    closedir(d);
  return n;
}

Test(image, save_into_a_missing_directory_fails)
{
  float rgb[3] = {0.5f, 0.5f, 0.5f};
  cr_redirect_stderr();
  cr_expect(!image_save(OUT_DIR "/no-such-dir/x.png", 1, 1, rgb, TONEMAP_CLAMP));
  cr_expect(!image_save(OUT_DIR "/no-such-dir/x.pfm", 1, 1, rgb, TONEMAP_CLAMP));
  struct stat st;
  cr_expect(stat(OUT_DIR "/no-such-dir", &st) != 0, "the directory was created");
}

Test(image, unknown_extension_is_rejected_and_writes_nothing)
{
  float rgb[3] = {0.5f, 0.5f, 0.5f};
  mkdir(OUT_DIR, 0755);
  remove(OUT_DIR "/x.bmp");
  remove(OUT_DIR "/noext");
  cr_redirect_stderr();
  cr_expect(!image_save(OUT_DIR "/x.bmp", 1, 1, rgb, TONEMAP_CLAMP));
  cr_expect(!image_save(OUT_DIR "/noext", 1, 1, rgb, TONEMAP_CLAMP));
  struct stat st;
  cr_expect(stat(OUT_DIR "/x.bmp", &st) != 0);
  cr_expect(stat(OUT_DIR "/noext", &st) != 0);
}

Test(image, failed_write_leaves_the_existing_file_untouched)
{
  /* An existing file, then a file-size limit of 1000 bytes (SIGXFSZ ignored,
   * so writes fail with EFBIG) and a 64 x 64 picture that cannot fit: the
   * write fails half way, the old file must be byte for byte the same and no
   * temporary file may be left. (Criterion runs each test in its own process.) */
  const char *dir = OUT_DIR "/atomic";
  mkdir(OUT_DIR, 0755);
  mkdir(dir, 0755);
  const char *paths[2] = {OUT_DIR "/atomic/keep.png", OUT_DIR "/atomic/keep.pfm"};
  const char old[] = "the previous picture, not to be lost\n";
  for (int k = 0; k < 2; k++) {
    FILE *f = fopen(paths[k], "wb");
    cr_assert(f && fwrite(old, 1, sizeof old - 1, f) == sizeof old - 1 && fclose(f) == 0);
  }
  static float rgb[64 * 64 * 3];
  uint32_t x = 12345;
  for (int k = 0; k < 64 * 64 * 3; k++) { /* noise (an LCG): PNG cannot shrink it */
    x = x * 1664525u + 1013904223u;
    rgb[k] = (float)(x >> 24) / 255.0f;
  }
  signal(SIGXFSZ, SIG_IGN);
  struct rlimit lim = {1000, 1000};
  cr_assert(setrlimit(RLIMIT_FSIZE, &lim) == 0);
  cr_redirect_stderr();
  for (int k = 0; k < 2; k++) {
    cr_expect(!image_save(paths[k], 64, 64, rgb, TONEMAP_CLAMP), "%s: save succeeded", paths[k]);
    char buf[256];
    long n = slurp(paths[k], buf, sizeof buf);
    cr_expect(n == (long)sizeof old - 1 && memcmp(buf, old, sizeof old - 1) == 0,
              "%s was changed", paths[k]);
  }
  cr_expect(count_files(dir, "keep.png.tmp") == 0, "a temporary .png file was left");
  cr_expect(count_files(dir, "keep.pfm.tmp") == 0, "a temporary .pfm file was left");
}

Test(image, save_replaces_an_existing_file)
{
  mkdir(OUT_DIR, 0755);
  const char *path = OUT_DIR "/replace.pfm";
  FILE *f = fopen(path, "wb");
  cr_assert(f);
  fputs("old", f);
  fclose(f);
  float rgb[3] = {0.25f, 0.5f, 2.0f};
  cr_assert(image_save(path, 1, 1, rgb, TONEMAP_CLAMP));
  float *back;
  int w, h;
  cr_assert(image_load(path, &w, &h, &back));
  cr_expect(w == 1 && h == 1 && back[0] == 0.25f && back[1] == 0.5f && back[2] == 2.0f);
  free(back);
}

Test(image, compare_counts_channels_over_the_tolerance)
{
  float a[6] = {0.0f, 0.5f, 1.0f, 0.2f, 0.2f, 0.2f};
  float b[6] = {0.0f, 0.6f, 1.0f, 0.2f, 0.25f, NAN};
  ImageDiff d = image_compare(2, 1, a, b, 0.07f);
  /* Over 0.07: the 0.1 difference and the NaN; not the 0.05 one. */
  cr_expect(d.over == 2, "over %ld", d.over);
  cr_expect(isnan(d.max_abs) || d.max_abs >= 0.1f - 1e-6f);
}
