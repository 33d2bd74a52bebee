/* Unit tests of film_to_byte (step 01), the export of a film value to a
 * byte: rounding at every code, clamping, NaN, and the sRGB and Reinhard tone
 * maps at values worked out by hand. docs/01-film.md, "What you write". */
#include "check.h"

#include "film.h"

#define DOC "docs/01-film.md, \"What you write\""

Test(export, byte_rounds_to_nearest_at_every_code)
{
  /* round(255 c): a value 0.02/255 below the midpoint of codes k and k+1
   * gives k, 0.02/255 above gives k+1 (far from the half, so the last bit of
   * 255 c does not matter). */
  Check c = CHECK("film_to_byte", DOC);
  for (int k = 0; k < 255; k++) {
    float below = (float)((k + 0.48L) / 255.0L), above = (float)((k + 0.52L) / 255.0L);
    float exact = (float)k / 255.0f;
    CHECK_INT(&c, k, film_to_byte(below, TONEMAP_CLAMP),
              "clamp tone map, c = (%d + 0.48)/255 = %.9g: round(255 c)", k, below);
    CHECK_INT(&c, k + 1, film_to_byte(above, TONEMAP_CLAMP),
              "clamp tone map, c = (%d + 0.52)/255 = %.9g: round(255 c)", k, above);
    CHECK_INT(&c, k, film_to_byte(exact, TONEMAP_CLAMP),
              "clamp tone map, c = %d/255 = %.9g: round(255 c)", k, exact);
  }
  CHECK_DONE(&c);
}

/* One film_to_byte case: the value, the tone map, the byte, and why. */
typedef struct ByteCase {
  float c;
  Tonemap tm;
  int byte;
  const char *why;
} ByteCase;

static void check_bytes(const ByteCase *cases, size_t n)
{
  static const char *const names[] = {"clamp", "srgb", "reinhard"};
  Check c = CHECK("film_to_byte", DOC);
  for (size_t k = 0; k < n; k++)
    CHECK_INT(&c, cases[k].byte, film_to_byte(cases[k].c, cases[k].tm),
              "%s tone map, c = %.9g: %s", names[cases[k].tm], cases[k].c, cases[k].why);
  CHECK_DONE(&c);
}

Test(export, byte_clamps_and_maps_nan_to_zero)
{
  const ByteCase cases[] = {
      {1.0f, TONEMAP_CLAMP, 255, "1 is the top code"},
      {0.999f, TONEMAP_CLAMP, 255, "254.745 rounds up"},
      {0.997f, TONEMAP_CLAMP, 254, "254.235 rounds down"},
      {1.5f, TONEMAP_CLAMP, 255, "above 1 clamps to 1"},
      {1e30f, TONEMAP_CLAMP, 255, "above 1 clamps to 1"},
      {INFINITY, TONEMAP_CLAMP, 255, "infinity clamps to 1"},
      {0.0f, TONEMAP_CLAMP, 0, "0"},
      {-0.0f, TONEMAP_CLAMP, 0, "-0"},
      {-0.5f, TONEMAP_CLAMP, 0, "negative clamps to 0"},
      {-INFINITY, TONEMAP_CLAMP, 0, "-infinity clamps to 0"},
      {NAN, TONEMAP_CLAMP, 0, "NaN gives 0"},
      {NAN, TONEMAP_SRGB, 0, "NaN gives 0"},
      {NAN, TONEMAP_REINHARD, 0, "NaN gives 0"},
      {-1.0f, TONEMAP_SRGB, 0, "negative gives 0"},
      {-1.0f, TONEMAP_REINHARD, 0, "negative gives 0"},
  };
  check_bytes(cases, sizeof cases / sizeof cases[0]);
}

Test(export, srgb_spot_values_by_hand)
{
  /* 12.92 c below 0.0031308, else 1.055 c^(1/2.4) - 0.055; times 255:
   *   0.002 -> 12.92 * 0.002 * 255                      =   6.589 -> 7
   *   0.18  -> 0.18^(1/2.4) = e^(-1.714798/2.4) = 0.489468,
   *            (1.055 * 0.489468 - 0.055) * 255         = 117.65 -> 118
   *   0.5   -> 0.5^(1/2.4) = 0.749154, (0.790357 - 0.055) * 255 = 187.52 -> 188
   *   1.0 -> 255, 2.0 clamps to 1.0 -> 255. Every value is far from a half. */
  const ByteCase cases[] = {
      {0.002f, TONEMAP_SRGB, 7, "12.92 c below 0.0031308: 6.589 -> 7"},
      {0.18f, TONEMAP_SRGB, 118, "1.055 c^(1/2.4) - 0.055: 117.65 -> 118"},
      {0.5f, TONEMAP_SRGB, 188, "1.055 c^(1/2.4) - 0.055: 187.52 -> 188"},
      {1.0f, TONEMAP_SRGB, 255, "1 -> 255"},
      {2.0f, TONEMAP_SRGB, 255, "clamped to 1 first"},
      {0.0f, TONEMAP_SRGB, 0, "0 -> 0"},
  };
  check_bytes(cases, sizeof cases / sizeof cases[0]);
}

Test(export, reinhard_spot_values_by_hand)
{
  /* c / (1 + c), then sRGB:
   *   1.0 -> 0.5  -> 188 (above)
   *   3.0 -> 0.75 -> 0.75^(1/2.4) = e^(-0.287682/2.4) = 0.887034,
   *                  (1.055 * 0.887034 - 0.055) * 255 = 224.61 -> 225
   *   0.25 -> 0.2 -> 0.2^(1/2.4) = e^(-1.609438/2.4) = 0.511402,
   *                  (0.539529 - 0.055) * 255 = 123.55 -> 124
   *   huge values tend to 1 -> 255, and so does infinity (its limit: the
   *   formula itself gives inf/inf = NaN). */
  const ByteCase cases[] = {
      {1.0f, TONEMAP_REINHARD, 188, "c / (1 + c) = 0.5, then sRGB: 187.52 -> 188"},
      {3.0f, TONEMAP_REINHARD, 225, "c / (1 + c) = 0.75, then sRGB: 224.61 -> 225"},
      {0.25f, TONEMAP_REINHARD, 124, "c / (1 + c) = 0.2, then sRGB: 123.55 -> 124"},
      {1e30f, TONEMAP_REINHARD, 255, "c / (1 + c) rounds to 1"},
      {INFINITY, TONEMAP_REINHARD, 255, "the limit of c / (1 + c) is 1 (inf/inf is NaN: "
                                        "handle infinity first)"},
  };
  check_bytes(cases, sizeof cases / sizeof cases[0]);
}
