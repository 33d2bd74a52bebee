/* Plain decimals read without strtof, exactly as it rounds them
 * (reader/decimal.h). */
#include "reader/decimal.h"

#include <float.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

/* 10^k, exact in double for k <= 22. */
static const double POW10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                 1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static const uint64_t POW10_U64[9] = {1, 10, 100, 1000, 10000, 100000, 1000000,
                                      10000000, 100000000};

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define NUMBER_WORDS 1
/* How many of the 8 bytes of x (first byte lowest) are digits before the
 * first one that is not: a byte is a digit when its high nibble is 3 and its
 * low nibble plus 6 does not carry into the high one. A borrow or carry only
 * runs from a byte to the ones after it, past the first byte that is not a
 * digit, so the count is exact. */
static int digits8(uint64_t x)
{
  uint64_t nib = 0xF0F0F0F0F0F0F0F0u;
  uint64_t other = ((x & nib) | (((x + 0x0606060606060606u) & nib) >> 4)) ^
                   0x3333333333333333u;
  return other ? __builtin_ctzll(other) >> 3 : 8;
}

/* The first n (1 to 8) digits of x as one number: the bytes after them
 * shifted out, zeros shifted in before them, then three multiplications
 * (Lemire's eight-digit reading). */
static uint64_t value8(uint64_t x, int n)
{
  uint64_t d = (x - 0x3030303030303030u) << (8 * (8 - n)), lo = 0x000000FF000000FFu;
  d = d * 10 + (d >> 8);
  return ((d & lo) * 0x000F424000000064u + ((d >> 16) & lo) * 0x0000271000000001u) >> 32;
}
#endif

/* The digits at s (up to end) appended to *v (v = 10 v + digit each, modulo
 * 2^64 like the plain loop), 8 bytes at a time where 8 are left (digits8,
 * value8); the byte loop for the last 7 bytes, and on machines that store
 * words big-end first. Returns where the digits stop. */
static const char *digit_run(const char *s, const char *end, uint64_t *v)
{
  uint64_t acc = *v;
#ifdef NUMBER_WORDS
  while (end - s >= 8) {
    uint64_t x;
    memcpy(&x, s, sizeof x);
    int n = digits8(x);
    if (n > 0) {
      acc = acc * POW10_U64[n] + value8(x, n);
      s += n;
    }
    if (n < 8) {
      *v = acc;
      return s;
    }
  }
#endif
  while (s < end && (unsigned)(*s - '0') < 10u)
    acc = acc * 10 + (uint64_t)(*s++ - '0');
  *v = acc;
  return s;
}

/* [sign] digits [. digits] [e [sign] digits] with at most 19 significant
 * digits, read from s up to the first byte that does not continue it (at
 * most to end): *m the digits as an integer, *e10 the power of ten to apply.
 * Returns where the reading stopped, NULL for no such decimal there (no
 * digit, more than 19 significant digits, an exponent with no digit). The
 * digits before the point in a plain loop (scenes write one to three there,
 * too few for eight bytes at a time), those after it by digit_run, the value
 * in a local: leading zeros add nothing to it, and are only counted apart when
 * there are more than 19 digits in all. */
static const char *decimal(const char *s, const char *end, bool *neg, uint64_t *m, int *e10)
{
  *neg = s < end && *s == '-';
  s += s < end && (*s == '-' || *s == '+');
  const char *first = s;
  uint64_t v = 0;
  while (s < end && (unsigned)(*s - '0') < 10u)
    v = v * 10 + (uint64_t)(*s++ - '0');
  int digits = (int)(s - first), frac = 0;
  if (s < end && *s == '.') {
    const char *point = s++;
    s = digit_run(s, end, &v);
    frac = (int)(s - point) - 1;
    digits += frac;
  }
  if (digits == 0)
    return NULL;
  if (digits > 19) { /* the significant ones: those after the leading zeros */
    int zeros = 0;
    for (const char *t = first; t < s && (*t == '0' || *t == '.'); t++)
      zeros += *t == '0';
    if (digits - zeros > 19)
      return NULL;
  }
  int exp = 0;
  if (s < end && (*s == 'e' || *s == 'E')) {
    s++;
    bool eneg = s < end && *s == '-';
    s += s < end && (*s == '-' || *s == '+');
    if (s == end || *s < '0' || *s > '9')
      return NULL;
    for (; s < end && *s >= '0' && *s <= '9'; s++)
      exp = exp < 100000 ? 10 * exp + (*s - '0') : exp;
    exp = eneg ? -exp : exp;
  }
  *m = v;
  *e10 = exp - frac;
  return s;
}

/* 10^-k rounded to double: a multiplication instead of a division, whose
 * latency is several times longer. */
static const double INV10[23] = {1e0,   1e-1,  1e-2,  1e-3,  1e-4,  1e-5,  1e-6,  1e-7,
                                 1e-8,  1e-9,  1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15,
                                 1e-16, 1e-17, 1e-18, 1e-19, 1e-20, 1e-21, 1e-22};

/* 10^k, exact in float for k <= 10 (5^10 < 2^24). */
static const float POW10F[11] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                 1e6f, 1e7f, 1e8f, 1e9f, 1e10f};

/* Double ulps around a midpoint between two floats: a double this close to
 * one goes to strtof. */
enum { NEAR_MIDPOINT = 4 };

/* m 10^e10 as strtof rounds it. When m < 2^24 and |e10| <= 10, m and
 * 10^|e10| are both floats, and one float product or quotient is the
 * correctly rounded value (Clinger's fast path; the scenes' numbers, written
 * with 6 or 7 significant digits, are such). Otherwise it is computed in
 * double (m < 2^53 exact): m times the exact 10^e10
 * (one rounding), or m times 10^e10 rounded (two roundings: within 2 double
 * ulps of the true value), then rounded to float. That last rounding gives
 * strtof's float unless a midpoint between two floats lies between the
 * double and the true value, which takes the double within 2 ulps of that
 * midpoint (its 29 bits below a float's near 0x10000000): those words, and
 * results outside the normal float range, go to strtof (false). */
static bool convert(bool neg, uint64_t m, int e10, float *out)
{
  if (m == 0) {
    *out = neg ? -0.0f : 0.0f;
    return true;
  }
  if (m < (1u << 24) && e10 >= -10 && e10 <= 10) {
    float f = (float)m;
    f = e10 >= 0 ? f * POW10F[e10] : f / POW10F[-e10];
    *out = neg ? -f : f;
    return true;
  }
  if (m >= (1ull << 53) || e10 < -22 || e10 > 22)
    return false;
  double r = (double)m * (e10 >= 0 ? POW10[e10] : INV10[-e10]);
  uint64_t bits;
  memcpy(&bits, &r, sizeof bits);
  uint64_t below = bits & 0x1fffffffu; /* the 29 bits below a float's */
  bool halfway = below - (0x10000000u - NEAR_MIDPOINT) <= 2 * NEAR_MIDPOINT;
  if (halfway || r < (double)FLT_MIN || r >= (double)FLT_MAX)
    return false;
  *out = neg ? -(float)r : (float)r;
  return true;
}

/* The words of a large scene's sphere lines (bench/gen_spheres writes them
 * with %.6g: -3.95543, 0.00123456): [-]D.F with 1 to 8 digits F, then a byte
 * that does not continue the word, and fewer than 2^24 digits D F in all.
 * What decimal and convert give for them (the same m and e10 = -n, then
 * Clinger's fast path), in one 8-byte word for F and without the stores of
 * the general path's results; NULL for any other word, and when fewer than
 * 12 bytes are left (decimal_prefix then takes the general path). */
static const char *short_decimal(const char *s, const char *end, float *out)
{
#ifdef NUMBER_WORDS
  if (end - s < 12)
    return NULL;
  bool neg = *s == '-';
  const char *p = s + neg;
  if ((unsigned)(p[0] - '0') >= 10u || p[1] != '.')
    return NULL;
  uint64_t x;
  memcpy(&x, p + 2, sizeof x);
  int n = digits8(x);
  char next = p[2 + n];
  if (n == 0 || (unsigned)(next - '0') < 10u || (next | 32) == 'e')
    return NULL;
  uint64_t m = (uint64_t)(p[0] - '0') * POW10_U64[n] + value8(x, n);
  if (m >= (1u << 24))
    return NULL;
  float f = (float)m / POW10F[n];
  *out = neg ? -f : f;
  return p + 2 + n;
#else
  (void)s, (void)end, (void)out;
  return NULL;
#endif
}

const char *decimal_prefix(const char *s, const char *end, float *out)
{
  bool neg;
  uint64_t m;
  int e10;
  const char *stop = short_decimal(s, end, out);
  if (stop)
    return stop;
  stop = decimal(s, end, &neg, &m, &e10);
  return stop && convert(neg, m, e10, out) ? stop : NULL;
}
