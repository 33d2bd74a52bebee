/* Helpers shared by the numerical stress tests (tests/stress_*.c): random
 * inputs, exact references in MPFR, ulp distances, and the Markdown tables
 * the tests write to build/stress/ for docs/accuracy.md. */
#ifndef RT_STRESS_H
#define RT_STRESS_H

#include <math.h>
#include <mpfr.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <criterion/criterion.h>

#include "rng.h"
#include "vec.h"

#ifndef BUILD_DIR
#define BUILD_DIR "build"
#endif
#define STRESS_DIR BUILD_DIR "/stress"

/* The step a stress test belongs to: the latest step whose functions it runs
 * (docs/accuracy.md). RT_STRESS_STEPS=K (make stress, make test-step K) runs
 * the tests of steps 01 .. K and skips the others, so that a student's run
 * never meets a step not written yet; RT_STRESS_ONLY=K runs step K's alone
 * (tests/run.sh runs the steps one by one, to reuse each step's result while
 * its code is unchanged); unset, every test runs. */
static inline void stress_step(int step)
{
  const char *upto = getenv("RT_STRESS_STEPS"), *only = getenv("RT_STRESS_ONLY");
  if (upto && *upto && step > atoi(upto))
    cr_skip_test("a stress test of step %02d (this run: steps 01 .. %02d)", step, atoi(upto));
  if (only && *only && step != atoi(only))
    cr_skip_test("a stress test of step %02d (this run: step %02d alone)", step, atoi(only));
}

/* MPFR precision of every reference: the inputs are floats (24-bit
 * significands with exponents within 2^-60 .. 2^60 of each other), so sums of
 * their products are exact at this width. */
enum { STRESS_PREC = 256 };

/* Uniform float in [lo, hi). */
static inline float stress_uniform(Rng *g, float lo, float hi)
{
  return lo + (hi - lo) * rng_float(g);
}

/* 10^u, u uniform in [lo, hi): log-uniform magnitudes. */
static inline double stress_log10u(Rng *g, double lo, double hi)
{
  return pow(10.0, lo + (hi - lo) * (double)rng_float(g));
}

/* A random unit vector (float, normalized in double then rounded). */
static inline vec3s stress_unit(Rng *g)
{
  for (;;) {
    double x = 2.0 * rng_float(g) - 1.0, y = 2.0 * rng_float(g) - 1.0,
           z = 2.0 * rng_float(g) - 1.0, n = sqrt(x * x + y * y + z * z);
    if (n > 0.1 && n <= 1.0)
      return vec_make((float)(x / n), (float)(y / n), (float)(z / n));
  }
}

/* A unit vector perpendicular to unit a (double precision, then float). */
static inline vec3s stress_perp(vec3s a, Rng *g)
{
  vec3s b = stress_unit(g);
  double k = (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z;
  double x = b.x - k * a.x, y = b.y - k * a.y, z = b.z - k * a.z;
  double n = sqrt(x * x + y * y + z * z);
  return vec_make((float)(x / n), (float)(y / n), (float)(z / n));
}

/* v and x as stored: read back through a volatile, the float the function
 * under test receives is the float the MPFR reference reads. The tests form
 * their inputs in double and round them to float; once link-time
 * optimisation inlines the function under test into the test, GCC 12's SLP
 * vectorizer can drop such a rounding where the function widens the value
 * back to double, and the function would then measure another ray than the
 * reference (docs/accuracy.md, "A GCC 12 bug"). */
static inline vec3s stress_stored(vec3s v)
{
  volatile vec3s stored = v;
  return stored;
}
static inline float stress_stored_f(float x)
{
  volatile float stored = x;
  return stored;
}

/* The size of one ulp of the float nearest to x (x finite). */
static inline double stress_ulp(double x)
{
  float f = fabsf((float)x);
  return (double)nextafterf(f, INFINITY) - (double)f;
}

/* An MPFR 3-vector and the operations the references need (all exact or
 * correctly rounded at STRESS_PREC bits). */
typedef struct M3 {
  mpfr_t c[3];
} M3;

static inline void m3_init(M3 *a)
{
  for (int k = 0; k < 3; k++)
    mpfr_init2(a->c[k], STRESS_PREC);
}
static inline void m3_clear(M3 *a)
{
  for (int k = 0; k < 3; k++)
    mpfr_clear(a->c[k]);
}
static inline void m3_set(M3 *a, vec3s v)
{
  for (int k = 0; k < 3; k++)
    mpfr_set_flt(a->c[k], v.raw[k], MPFR_RNDN);
}
static inline void m3_sub(M3 *r, const M3 *a, const M3 *b)
{
  for (int k = 0; k < 3; k++)
    mpfr_sub(r->c[k], a->c[k], b->c[k], MPFR_RNDN);
}
/* r = a + s b */
static inline void m3_axpy(M3 *r, const M3 *a, mpfr_srcptr s, const M3 *b)
{
  mpfr_t tmp;
  mpfr_init2(tmp, STRESS_PREC);
  for (int k = 0; k < 3; k++) {
    mpfr_mul(tmp, s, b->c[k], MPFR_RNDN);
    mpfr_add(r->c[k], a->c[k], tmp, MPFR_RNDN);
  }
  mpfr_clear(tmp);
}
static inline void m3_dot(mpfr_ptr r, const M3 *a, const M3 *b)
{
  mpfr_t tmp;
  mpfr_init2(tmp, STRESS_PREC);
  mpfr_mul(r, a->c[0], b->c[0], MPFR_RNDN);
  for (int k = 1; k < 3; k++) {
    mpfr_mul(tmp, a->c[k], b->c[k], MPFR_RNDN);
    mpfr_add(r, r, tmp, MPFR_RNDN);
  }
  mpfr_clear(tmp);
}

/* Start (truncate) the table file build/stress/NAME.md with a title line and a
 * header; stress_row appends one line. Both print the line to stdout too. */
static inline void stress_table(const char *name, const char *title, const char *header)
{
  char path[256];
  mkdir(BUILD_DIR, 0777);
  mkdir(STRESS_DIR, 0777);
  snprintf(path, sizeof path, STRESS_DIR "/%s.md", name);
  FILE *f = fopen(path, "w");
  if (f) {
    fprintf(f, "%s\n\n%s\n", title, header);
    fclose(f);
  }
}

__attribute__((format(printf, 2, 3)))
static inline void stress_row(const char *name, const char *fmt, ...)
{
  char path[256];
  snprintf(path, sizeof path, STRESS_DIR "/%s.md", name);
  FILE *f = fopen(path, "a");
  va_list ap;
  va_start(ap, fmt);
  if (f) {
    vfprintf(f, fmt, ap);
    fputc('\n', f);
    fclose(f);
  }
  va_end(ap);
}

#endif
