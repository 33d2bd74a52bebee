/* Unit tests of image files (step 01): an asymmetric "F" picture saved as
 * PNG and PFM and read back (flips and R/B swaps fail), tone map names,
 * atomic writes, image comparison. docs/01-film.md. film_to_byte itself is
 * tested in tests/test_export.c. */
#include "check.h"

#include <criterion/redirect.h>

#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include "threads.h"
#include <png.h>
#include <stb_image.h>

#include "app/image.h"
#include "testfiles.h"

#define OUT_DIR BUILD_DIR "/test-out"
#define DOC "docs/01-film.md, \"What you write\""
#define FILES "docs/01-film.md, \"The math\""

/* A file operation the rest of a test needs (image files are given code). */
#define REQUIRE(ok, ...)                                                         \
  do {                                                                           \
    Check req_ = CHECK("image_save, image_load", FILES);                         \
    CHECK_REQUIRE(&req_, ok, __VA_ARGS__);                                       \
  } while (0)

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
  REQUIRE(image_save(path, F_W, F_H, rgb, TONEMAP_CLAMP), "cannot write %s", path);

  /* The file itself, read by stb: top row first, R G B order. The bytes come
   * from film_to_byte (k / 255 gives k back). */
  int w, h, n;
  unsigned char *px = stbi_load(path, &w, &h, &n, 3);
  REQUIRE(px && w == F_W && h == F_H, "%s is not a 5 x 7 PNG", path);
  Check c = CHECK("film_to_byte (through image_save)", DOC);
  for (int row = 0; row < F_H; row++)
    for (int i = 0; i < F_W; i++) {
      unsigned char b[3];
      letter_bytes(F_ROWS[row][i], b);
      const unsigned char *got = px + (row * F_W + i) * 3;
      CHECK_THAT(&c, memcmp(got, b, 3) == 0,
                 "the F picture's PNG, row %d from the top, column %d ('%c')\n"
                 "  expected %d %d %d\n  got      %d %d %d", row, i, F_ROWS[row][i],
                 b[0], b[1], b[2], got[0], got[1], got[2]);
    }
  CHECK_DONE(&c);

  /* image_load gives the file's bytes / 255 back, rows bottom first. */
  float *back;
  REQUIRE(image_load(path, &w, &h, &back), "cannot read %s back", path);
  REQUIRE(w == F_W && h == F_H, "%s read back as %d x %d, not 5 x 7", path, w, h);
  Check l = CHECK("image_load", FILES);
  for (int k = 0; k < F_W * F_H * 3; k++) {
    int i = (k / 3) % F_W, j = (k / 3) / F_W;
    float want = px[((F_H - 1 - j) * F_W + i) * 3 + k % 3] / 255.0f;
    CHECK_NEAR(&l, want, back[k], 0.0, "the F picture's PNG read back: float %d (pixel %d, %d "
               "from the bottom left), the file's byte / 255", k, i, j);
  }
  CHECK_DONE(&l);
  stbi_image_free(px);
  free(back);
}

/* A picture taller than one band of the PNG encoder (its rows are compressed
 * in bands of at least 64 KB, one band per thread at a time:
 * docs/performance.md, "PNG in bands"), read back through libpng, which
 * checks every chunk's CRC and the stream's Adler-32: each byte is the one
 * chosen, and the file is the same with 1 thread and with 4. */
Test(image, png_in_bands_reads_back_through_libpng_the_same_for_any_thread_count)
{
  enum { W = 301, H = 517 }; /* 906 bytes a row: 73 rows a band, 8 bands */
  /* Bytes chosen first, the film holding byte / 255 (film_to_byte gives k
   * back for k / 255, as in the F picture): ramps with noise, so that the
   * Sub filter and deflate see both smooth runs and changes. */
  float *rgb = malloc((size_t)W * H * 3 * sizeof *rgb);
  unsigned char *want = malloc((size_t)W * H * 3);
  REQUIRE(rgb && want, "out of memory");
  uint32_t x = 12345u;
  for (int k = 0; k < W * H * 3; k++) {
    int i = (k / 3) % W, row = (k / 3) / W, c = k % 3; /* row from the top */
    x = x * 1664525u + 1013904223u;
    unsigned char byte = (unsigned char)((3 * i + 5 * row + 40 * c + (int)(x >> 29)) % 256);
    want[k] = byte;
    rgb[((H - 1 - row) * W + i) * 3 + c] = byte / 255.0f;
  }
  mkdir(OUT_DIR, 0755);
  const char *paths[2] = {OUT_DIR "/bands-1.png", OUT_DIR "/bands-4.png"};
  int threads[2] = {1, 4};
  for (int k = 0; k < 2; k++) {
    omp_set_num_threads(threads[k]);
    REQUIRE(image_save(paths[k], W, H, rgb, TONEMAP_CLAMP), "cannot write %s", paths[k]);
  }
  long len[2] = {0, 0};
  char *file[2] = {testfiles_slurp(paths[0], &len[0]), testfiles_slurp(paths[1], &len[1])};
  REQUIRE(file[0] && file[1], "cannot read %s and %s back", paths[0], paths[1]);
  Check same = CHECK("image_save (PNG)", FILES);
  CHECK_THAT(&same, len[0] == len[1] && memcmp(file[0], file[1], (size_t)len[0]) == 0,
             "the PNG of a %d x %d picture differs between 1 thread (%ld bytes) and 4 "
             "(%ld bytes)", W, H, len[0], len[1]);
  CHECK_DONE(&same);

  png_image im = {.version = PNG_IMAGE_VERSION};
  unsigned char *px = malloc((size_t)W * H * 3);
  REQUIRE(px && png_image_begin_read_from_memory(&im, file[1], (size_t)len[1]),
          "libpng cannot read %s back: %s", paths[1], im.message);
  REQUIRE(im.width == W && im.height == H, "%s read back as %u x %u, not %d x %d", paths[1],
          im.width, im.height, W, H);
  im.format = PNG_FORMAT_RGB;
  REQUIRE(png_image_finish_read(&im, NULL, px, 0, NULL), "libpng cannot read %s back: %s",
          paths[1], im.message);
  Check c = CHECK("film_to_byte (through image_save)", DOC);
  for (int k = 0; k < W * H * 3; k++)
    CHECK_THAT(&c, px[k] == want[k], "the %d x %d PNG read back by libpng, row %d from the "
               "top, column %d, channel %d (the film holds %d / 255)\n  expected %d\n  "
               "got      %d", W, H, (k / 3) / W, (k / 3) % W, k % 3, want[k], want[k], px[k]);
  CHECK_DONE(&c);
  png_image_free(&im);
  free(px);
  free(file[0]);
  free(file[1]);
  free(want);
  free(rgb);
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
  REQUIRE(image_save(path, F_W, F_H, rgb, TONEMAP_CLAMP), "cannot write %s", path);

  /* PFM: "PF\n5 7\n-1.0\n" (negative scale = little-endian), then the rows
   * from the BOTTOM of the picture: the first pixel is the F's foot (red),
   * the fifth the green one. */
  FILE *f = fopen(path, "rb");
  REQUIRE(f, "cannot open %s", path);
  unsigned char buf[64 + F_W * F_H * 12];
  size_t got = fread(buf, 1, sizeof buf, f);
  fclose(f);
  const char head[] = "PF\n5 7\n-1.0\n";
  size_t hl = sizeof head - 1;
  REQUIRE(got == hl + F_W * F_H * 12, "%s has %zu bytes, expected %zu", path, got,
          hl + F_W * F_H * 12);
  REQUIRE(memcmp(buf, head, hl) == 0, "%s's header is '%.*s', expected 'PF 5 7 -1.0'", path,
          (int)hl, buf);
  Check ck = CHECK("image_save", FILES);
  for (int j = 0; j < F_H; j++)
    for (int i = 0; i < F_W; i++) {
      unsigned char b[3];
      letter_bytes(F_ROWS[F_H - 1 - j][i], b);
      for (int c = 0; c < 3; c++)
        CHECK_NEAR(&ck, b[c] / 255.0f, le_float(buf + hl + ((j * F_W + i) * 3 + c) * 4), 0.0,
                   "the F picture's PFM, pixel (%d, %d) from the bottom left, channel %d",
                   i, j, c);
    }
  CHECK_DONE(&ck);

  float *back;
  int w, h;
  REQUIRE(image_load(path, &w, &h, &back), "cannot read %s back", path);
  REQUIRE(w == F_W && h == F_H, "%s read back as %d x %d, not 5 x 7", path, w, h);
  Check l = CHECK("image_load", FILES);
  CHECK_THAT(&l, memcmp(back, rgb, sizeof rgb) == 0, "the F picture's PFM read back: "
             "some floats changed");
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
  REQUIRE(image_save(path, 3, 2, rgb, TONEMAP_REINHARD), "cannot write %s", path);
  float *back;
  int w, h;
  REQUIRE(image_load(path, &w, &h, &back), "cannot read %s back", path);
  REQUIRE(w == 3 && h == 2, "%s read back as %d x %d, not 3 x 2", path, w, h);
  Check c = CHECK("image_save, image_load", FILES);
  CHECK_THAT(&c, memcmp(back, rgb, sizeof rgb) == 0, "a PFM of HDR, negative, subnormal and "
             "infinite values read back: some bits changed");
  free(back);
}

Test(image, tonemap_names_parse)
{
  const char *const names[] = {"clamp", "srgb", "reinhard"};
  Check c = CHECK("image_tonemap_parse", "docs/01-film.md, \"The math\"");
  for (int k = 0; k < 3; k++) {
    Tonemap t = (Tonemap)-1;
    bool ok = image_tonemap_parse(names[k], &t);
    CHECK_THAT(&c, ok && t == (Tonemap)k, "'%s' is tone map %d, got %s %d", names[k], k,
               ok ? "accepted as" : "rejected,", (int)t);
  }
  Tonemap t;
  CHECK_INT(&c, 0, image_tonemap_parse("aces", &t), "'aces' is not a tone map");
  CHECK_INT(&c, 0, image_tonemap_parse("", &t), "'' is not a tone map");
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

Test(image, save_into_a_missing_directory_fails)
{
  float rgb[3] = {0.5f, 0.5f, 0.5f};
  cr_redirect_stderr();
  Check c = CHECK("image_save", FILES);
  CHECK_INT(&c, 0, image_save(OUT_DIR "/no-such-dir/x.png", 1, 1, rgb, TONEMAP_CLAMP),
            "saving a PNG into a missing folder: the result (false)");
  CHECK_INT(&c, 0, image_save(OUT_DIR "/no-such-dir/x.pfm", 1, 1, rgb, TONEMAP_CLAMP),
            "saving a PFM into a missing folder: the result (false)");
  struct stat st;
  CHECK_THAT(&c, stat(OUT_DIR "/no-such-dir", &st) != 0, "the missing folder was created");
}

Test(image, unknown_extension_is_rejected_and_writes_nothing)
{
  float rgb[3] = {0.5f, 0.5f, 0.5f};
  mkdir(OUT_DIR, 0755);
  remove(OUT_DIR "/x.bmp");
  remove(OUT_DIR "/noext");
  cr_redirect_stderr();
  Check c = CHECK("image_save", FILES);
  CHECK_INT(&c, 0, image_save(OUT_DIR "/x.bmp", 1, 1, rgb, TONEMAP_CLAMP),
            "saving x.bmp (unknown format): the result (false)");
  CHECK_INT(&c, 0, image_save(OUT_DIR "/noext", 1, 1, rgb, TONEMAP_CLAMP),
            "saving 'noext' (no extension): the result (false)");
  struct stat st;
  CHECK_THAT(&c, stat(OUT_DIR "/x.bmp", &st) != 0, "x.bmp was written");
  CHECK_THAT(&c, stat(OUT_DIR "/noext", &st) != 0, "'noext' was written");
}

Test(image, failed_write_leaves_the_existing_file_untouched)
{
  /* An existing file, then a file-size limit of 1000 bytes (SIGXFSZ ignored,
   * so writes fail with EFBIG) and a 1024 x 1024 picture that cannot fit
   * whatever bytes film_to_byte gives (deflate shrinks at most about 1000
   * times): the write fails half way, the old file must be byte for byte the
   * same and no temporary file may be left. (Criterion runs each test in its
   * own process.) */
  const char *dir = OUT_DIR "/atomic";
  mkdir(OUT_DIR, 0755);
  mkdir(dir, 0755);
  const char *paths[2] = {OUT_DIR "/atomic/keep.png", OUT_DIR "/atomic/keep.pfm"};
  const char old[] = "the previous picture, not to be lost\n";
  for (int k = 0; k < 2; k++) {
    FILE *f = fopen(paths[k], "wb");
    REQUIRE(f && fwrite(old, 1, sizeof old - 1, f) == sizeof old - 1 && fclose(f) == 0,
            "cannot write %s", paths[k]);
  }
  enum { SIDE = 1024 };
  static float rgb[SIDE * SIDE * 3];
  uint32_t x = 12345;
  for (int k = 0; k < SIDE * SIDE * 3; k++) { /* noise (an LCG) */
    x = x * 1664525u + 1013904223u;
    rgb[k] = (float)(x >> 24) / 255.0f;
  }
  /* The PNG is compressed by several threads: start the OpenMP runtime first,
   * as a render does. LLVM's (make sanitize-clang) writes a shared-memory file
   * when it starts, which a 1000-byte limit refuses, and then stops. */
  (void)omp_get_max_threads();
  signal(SIGXFSZ, SIG_IGN);
  struct rlimit lim = {1000, 1000};
  REQUIRE(setrlimit(RLIMIT_FSIZE, &lim) == 0, "setrlimit(RLIMIT_FSIZE) failed");
  cr_redirect_stderr();
  Check c = CHECK("image_save", FILES);
  for (int k = 0; k < 2; k++) {
    CHECK_INT(&c, 0, image_save(paths[k], SIDE, SIDE, rgb, TONEMAP_CLAMP),
              "%s over a 1000-byte file-size limit: the result (false)", paths[k]);
    char buf[256];
    long n = slurp(paths[k], buf, sizeof buf);
    CHECK_THAT(&c, n == (long)sizeof old - 1 && memcmp(buf, old, sizeof old - 1) == 0,
               "a failed write changed the existing %s", paths[k]);
  }
  CHECK_INT(&c, 0, testfiles_count(dir, "keep.png.tmp"), "temporary .png files left behind");
  CHECK_INT(&c, 0, testfiles_count(dir, "keep.pfm.tmp"), "temporary .pfm files left behind");
}

Test(image, save_replaces_an_existing_file)
{
  mkdir(OUT_DIR, 0755);
  const char *path = OUT_DIR "/replace.pfm";
  FILE *f = fopen(path, "wb");
  REQUIRE(f, "cannot write %s", path);
  fputs("old", f);
  fclose(f);
  float rgb[3] = {0.25f, 0.5f, 2.0f};
  REQUIRE(image_save(path, 1, 1, rgb, TONEMAP_CLAMP), "cannot replace %s", path);
  float *back;
  int w, h;
  REQUIRE(image_load(path, &w, &h, &back), "cannot read %s back", path);
  Check c = CHECK("image_save", FILES);
  CHECK_THAT(&c, w == 1 && h == 1, "the replaced file is a 1 x 1 PFM, got %d x %d", w, h);
  CHECK_VEC(&c, vec_make(0.25f, 0.5f, 2.0f), vec_make(back[0], back[1], back[2]), 0.0,
            "the replaced file's pixel");
  free(back);
}

Test(image, compare_counts_channels_over_the_tolerance)
{
  float a[6] = {0.0f, 0.5f, 1.0f, 0.2f, 0.2f, 0.2f};
  float b[6] = {0.0f, 0.6f, 1.0f, 0.2f, 0.25f, NAN};
  ImageDiff d = image_compare(2, 1, a, b, 0.07f);
  /* Over 0.07: the 0.1 difference and the NaN; not the 0.05 one. */
  Check c = CHECK("image_compare", "docs/testing.md, \"The image test\"");
  CHECK_INT(&c, 2, d.over, "channels over 0.07 among differences 0, 0.1, 0, 0, 0.05, NaN");
  CHECK_THAT(&c, isnan(d.max_abs) || d.max_abs >= 0.1f - 1e-6f,
             "the largest difference: NaN or at least 0.1, got %.9g", d.max_abs);
}
