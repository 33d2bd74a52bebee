/* Tests of the scene format's number reader (step 02): number_parse must
 * give, bit for bit, the float C's strtof gives for the same word, on random
 * decimals and on words next to the halfway points between two floats (where
 * a double rounding would differ), and must sort the others into bad,
 * non-finite and too small. docs/scene-format.md, "Numbers". */
#include "check.h"

#include <errno.h>
#include <float.h>
#include <stdlib.h>

#include "app/number.h"
#include "reader/decimal.h"

#define DOC "docs/scene-format.md, \"Numbers\""

/* A small generator (xorshift64*), seeded: the same words every run. */
static uint64_t next(uint64_t *s)
{
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return *s * 2685821657736338717ull;
}

/* What strtof says of `word`, with the reader's classification. */
static NumberStatus reference(const char *word, float *out)
{
  char *end;
  errno = 0;
  float v = strtof(word, &end);
  if (end == word || *end != '\0')
    return NUMBER_BAD;
  if (!isfinite(v))
    return NUMBER_NONFINITE;
  if ((v != 0.0f && fabsf(v) < FLT_MIN) || (v == 0.0f && errno == ERANGE))
    return NUMBER_TINY;
  *out = v;
  return NUMBER_OK;
}

/* One word through both; counts a failure on any difference. */
static void same_as_strtof(Check *c, const char *word)
{
  float want = 0.0f, got = 0.0f;
  NumberStatus ws = reference(word, &want);
  NumberStatus gs = number_parse(word, (int)strlen(word), &got);
  uint32_t wb, gb;
  memcpy(&wb, &want, 4);
  memcpy(&gb, &got, 4);
  CHECK_THAT(c, ws == gs && (ws != NUMBER_OK || wb == gb),
             "'%s'\n  expected status %d, strtof's float %.9g (bits 0x%08x)\n  got      "
             "status %d, float %.9g (bits 0x%08x)", word, (int)ws, (double)want, wb, (int)gs,
             (double)got, gb);
}

/* A random decimal: sign, 1 to 21 digits with a point somewhere, an
 * exponent from -45 to 45 written in one of three ways. */
static void random_word(uint64_t *s, char *out, size_t size)
{
  char digits[32];
  int n = 1 + (int)(next(s) % 21), point = (int)(next(s) % (uint64_t)(n + 2)) - 1;
  for (int k = 0; k < n; k++)
    digits[k] = (char)('0' + next(s) % 10);
  int len = 0, e = (int)(next(s) % 91) - 45, style = (int)(next(s) % 3);
  const char *sign = next(s) % 4 == 0 ? "-" : next(s) % 8 == 0 ? "+" : "";
  len += snprintf(out + len, size - (size_t)len, "%s", sign);
  for (int k = 0; k < n; k++) {
    if (k == point)
      out[len++] = '.';
    out[len++] = digits[k];
  }
  if (point == n)
    out[len++] = '.';
  out[len] = '\0';
  if (style == 1)
    snprintf(out + len, size - (size_t)len, "e%d", e);
  else if (style == 2)
    snprintf(out + len, size - (size_t)len, "E%+03d", e);
}

Test(number, random_decimals_round_like_strtof, .timeout = 60)
{
  Check c = CHECK("number_parse", DOC);
  uint64_t s = 0x9E3779B97F4A7C15ull;
  char word[64];
  for (int k = 0; k < 300000; k++) {
    random_word(&s, word, sizeof word);
    same_as_strtof(&c, word);
  }
  CHECK_DONE(&c);
}

/* Words around the point halfway between a float and the next one up: a
 * double rounded to nearest may land exactly on it, and then rounding that
 * double to float picks by ties-to-even where strtof looks at the true value. */
Test(number, words_next_to_halfway_points_round_like_strtof, .timeout = 60)
{
  Check c = CHECK("number_parse", DOC);
  uint64_t s = 0xD1B54A32D192ED03ull;
  char word[96];
  for (int k = 0; k < 100000; k++) {
    uint32_t bits = (uint32_t)(next(&s) % 0x7f000000u) + 0x00800000u; /* normal floats */
    float f, up;
    memcpy(&f, &bits, 4);
    up = nextafterf(f, INFINITY);
    double mid = 0.5 * ((double)f + (double)up); /* exact in double */
    for (int digits = 6; digits <= 19; digits += 1 + (int)(next(&s) % 4)) {
      snprintf(word, sizeof word, "%.*e", digits, mid);
      same_as_strtof(&c, word);
    }
    snprintf(word, sizeof word, "%.17g", mid);
    same_as_strtof(&c, word);
  }
  /* Integers that are exact halfway points: 2^24 + 1 lies between 2^24 and
   * 2^24 + 2 and rounds to the even one, 2^24. */
  static const char *const ties[] = {"16777217", "16777219", "33554434", "-16777217",
                                     "1677721.7e1", "0.16777217e8", "9007199254740993",
                                     "3.4028235677973366e38", "1.1754942807573643e-38"};
  for (size_t k = 0; k < sizeof ties / sizeof ties[0]; k++)
    same_as_strtof(&c, ties[k]);
  CHECK_DONE(&c);
}

Test(number, words_that_are_not_plain_finite_floats)
{
  static const struct {
    const char *word;
    NumberStatus want;
  } cases[] = {
      {"inf", NUMBER_NONFINITE},      {"-Infinity", NUMBER_NONFINITE},
      {"nan", NUMBER_NONFINITE},      {"NAN(123)", NUMBER_NONFINITE},
      {"1e39", NUMBER_NONFINITE},     {"-3.5e38", NUMBER_NONFINITE},
      {"1e999999999", NUMBER_NONFINITE}, {"1e-40", NUMBER_TINY},
      {"1e-50", NUMBER_TINY},         {"0x1p-149", NUMBER_TINY},
      {"-1e-45", NUMBER_TINY},        {"1.17549421e-38", NUMBER_TINY},
      {"", NUMBER_BAD},               {".", NUMBER_BAD},
      {"+", NUMBER_BAD},              {"1e", NUMBER_BAD},
      {"1e+", NUMBER_BAD},            {"1.5.2", NUMBER_BAD},
      {"0x", NUMBER_BAD},             {"1,5", NUMBER_BAD},
      {"1f", NUMBER_BAD},             {"--1", NUMBER_BAD},
      {"0", NUMBER_OK},               {"-0", NUMBER_OK},
      {"0e999999", NUMBER_OK},        {"1.", NUMBER_OK},
      {".5", NUMBER_OK},              {"0x1p-2", NUMBER_OK},
      {"3.40282347e38", NUMBER_OK},   {"1.17549435e-38", NUMBER_OK},
  };
  Check c = CHECK("number_parse", DOC);
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    float v = 0.0f;
    NumberStatus got = number_parse(cases[k].word, (int)strlen(cases[k].word), &v);
    CHECK_INT(&c, cases[k].want, got, "'%s': status (0 ok, 1 not a number, 2 non-finite, "
              "3 below FLT_MIN)", cases[k].word);
    same_as_strtof(&c, cases[k].word);
  }
  float z = 1.0f;
  number_parse("-0", 2, &z);
  CHECK_THAT(&c, z == 0.0f && signbit(z), "'-0': expected negative zero, as strtof, got %g", z);
  CHECK_DONE(&c);
}

Test(number, reads_only_the_bytes_it_is_given)
{
  /* The scene text is not cut into terminated words: "12" of "1234". */
  Check c = CHECK("number_parse", DOC);
  float v = 0.0f;
  CHECK_INT(&c, NUMBER_OK, number_parse("1234", 2, &v), "the first 2 bytes of \"1234\"");
  CHECK_NEAR(&c, 12.0, v, 0.0, "the first 2 bytes of \"1234\": value");
  CHECK_INT(&c, NUMBER_OK, number_parse("0x1p3zzz", 5, &v), "the first 5 bytes of "
            "\"0x1p3zzz\" (a hex float, read by strtof from a copy)");
  CHECK_NEAR(&c, 8.0, v, 0.0, "\"0x1p3\": value");
}

/* decimal_prefix, as the parser's fast path calls it: on the scene text, which
 * goes on after the word. Each random word is followed by a byte that ends
 * it (a space, a newline, '#') or may continue it ('.', 'e', a digit,
 * 'x'), then 20 more bytes (the reader looks at 8 bytes at a time), or in
 * every fifth word nothing more (it reads words of the form [-]D.F apart when
 * 12 bytes are left); where decimal_prefix reads a number, it must be
 * number_parse's float for the bytes it read, and it must stop at the end of
 * a word the next byte ends. Plain decimals of fewer than 8 digits on each
 * side of the point, as scenes write them (%g, %.6f, %.6g), must be read. */
Test(number, prefix_reads_as_number_parse_up_to_where_it_stops, .timeout = 60)
{
  Check c = CHECK("decimal_prefix", DOC);
  uint64_t s = 0x5851F42D4C957F2Dull;
  static const char after[] = " \n#.e5x";
  static const char *const odd[] = {".", "-", "+", "-.", "5.", ".5", "0.", "-0", "00000001.5",
                                    "1234567.1234567", "12345678", "1.12345678", "7e", "1.5e3",
                                    "0.00123456", "-0.00123456", "1.123456789", "9.99999999",
                                    "-1.6777216", "1.6777215", "-0.0", "0.5E1", "1.5e", "-.5"};
  const int n_odd = (int)(sizeof odd / sizeof *odd);
  for (int k = 0; k < 300000 + n_odd; k++) {
    char word[64], text[128];
    bool plain = k >= n_odd && k % 2;
    if (k < n_odd) {
      snprintf(word, sizeof word, "%s", odd[k]);
    } else if (plain) {
      double v = (double)(next(&s) % 20000001) / 1000.0 - 10000.0;
      snprintf(word, sizeof word, k % 6 == 1 ? "%g" : k % 6 == 3 ? "%.6f" : "%.6g",
               v / pow(10.0, (double)(next(&s) % 8)));
    } else {
      random_word(&s, word, sizeof word);
    }
    int len = (int)strlen(word);
    char end = after[next(&s) % (sizeof after - 1)];
    memcpy(text, word, (size_t)len);
    text[len] = end;
    for (int j = 1; j <= 20; j++) /* printable, or in a third of the words any byte */
      text[len + j] = (char)(k % 3 ? ' ' + next(&s) % 95 : 1 + next(&s) % 255);
    float got = 0.0f, want = 0.0f;
    const char *stop = decimal_prefix(text, text + len + (k % 5 ? 21 : 1), &got);
    bool ends = end == ' ' || end == '\n' || end == '#';
    if (!stop) {
      CHECK_THAT(&c, !(plain && ends), "'%s' then '%c': expected a number read, got none",
                 word, end);
      continue;
    }
    NumberStatus st = number_parse(text, (int)(stop - text), &want);
    uint32_t wb, gb;
    memcpy(&wb, &want, 4);
    memcpy(&gb, &got, 4);
    CHECK_THAT(&c, st == NUMBER_OK && wb == gb && (!ends || stop == text + len),
               "'%s' then '%c': read %d bytes as %.9g (bits 0x%08x); expected %s%d bytes, "
               "number_parse's float for them %.9g (bits 0x%08x, status %d)", word, end,
               (int)(stop - text), (double)got, gb, ends ? "" : "up to ", len, (double)want,
               wb, (int)st);
  }
  CHECK_DONE(&c);
}
