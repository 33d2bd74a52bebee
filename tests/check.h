/* Checks that read as lessons: a failing check names the function under test
 * and the doc section to read, and shows what was expected and what came
 * back, in decimal. A test that loops over many cases reports its first
 * CHECK_SHOWN failures, then (CHECK_DONE) how many failed in all.
 *
 *   Check c = CHECK("sphere_hit_t", "docs/02-intersection.md, \"What you write\"");
 *   CHECK_NEAR(&c, 4.0, t, 0.0, "ray from the origin along -z, unit sphere at z = -5: t");
 *   CHECK_DONE(&c);
 *
 * prints, when t is wrong,
 *
 *   sphere_hit_t: ray from the origin along -z, unit sphere at z = -5: t
 *     expected 4
 *     got      inf
 *     read docs/02-intersection.md, "What you write"
 *
 * (Criterion indents each line by two more spaces.) CHECK_RELYING also names
 * the earlier steps' functions a test runs ("this test also runs ..."), and
 * CHECK_REQUIRE stops the test when a precondition fails. tests/run.sh reads
 * the function and the doc back from these messages for its verdict lines;
 * docs/testing.md, "Messages".
 */
#ifndef RT_CHECK_H
#define RT_CHECK_H

#include <criterion/criterion.h>

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "vec.h"

enum { CHECK_SHOWN = 3, CHECK_TEXT = 4096 };

typedef struct Check {
  const char *fn;     /* the function under test, "sphere_hit_t" */
  const char *doc;    /* where its doc explains it, "docs/02-intersection.md, \"What you write\"" */
  int cases;          /* cases checked so far */
  int failed;         /* of which failed */
  const char *relies; /* earlier steps' functions the test also runs, or NULL */
} Check;

#define CHECK(fn, doc) ((Check){(fn), (doc), 0, 0, NULL})

/* A check of a function that can only be reached through earlier steps'
 * functions: a failure also names those, so that a student whose earlier
 * step is wrong fixes that first ("light_incident (step 04)"). */
#define CHECK_RELYING(fn, doc, relies) ((Check){(fn), (doc), 0, 0, (relies)})

/* "" or the line naming what the test also relies on. */
static inline const char *check_relies_(const Check *c, char *buf, size_t size)
{
  if (!c->relies)
    return "";
  snprintf(buf, size, "\n  this test also runs %s: if their tests fail too, fix those first",
           c->relies);
  return buf;
}

/* check_relies_ with a buffer of its own (inside one macro call). */
#define CHECK_RELIES_(c) check_relies_((c), (char[CHECK_TEXT]){0}, CHECK_TEXT)

/* Count a case; true when it failed and is among the first CHECK_SHOWN. */
static inline bool check_show_(Check *c, bool ok)
{
  c->cases++;
  return !ok && ++c->failed <= CHECK_SHOWN;
}

/* Distance between two floats in units in the last place (0 when equal,
 * huge when either is NaN or they differ in sign by more than zero). */
static inline int64_t check_ulps(float a, float b)
{
  if (a == b)
    return 0;
  if (isnan(a) || isnan(b))
    return INT64_MAX;
  int32_t ia, ib;
  memcpy(&ia, &a, sizeof ia);
  memcpy(&ib, &b, sizeof ib);
  int64_t ka = ia < 0 ? (int64_t)INT32_MIN - ia : ia, kb = ib < 0 ? (int64_t)INT32_MIN - ib : ib;
  return ka > kb ? ka - kb : kb - ka;
}

/* " (within 1e-05)", or "" when tol is 0. */
static inline const char *check_within_(char *buf, size_t size, double tol)
{
  if (tol > 0.0)
    snprintf(buf, size, " (within %.3g)", tol);
  else
    buf[0] = 0;
  return buf;
}

/* The general form: `ok`, and a message (printf arguments) that says the case,
 * what was expected and what came back. */
#define CHECK_THAT(c, ok, ...)                                                  \
  do {                                                                          \
    if (check_show_((c), (ok))) {                                               \
      char check_what_[CHECK_TEXT];                                             \
      snprintf(check_what_, sizeof check_what_, __VA_ARGS__);                   \
      cr_expect(0, "%s: %s\n  read %s%s", (c)->fn, check_what_, (c)->doc,        \
                CHECK_RELIES_(c));                                              \
    }                                                                           \
  } while (0)

/* A precondition the rest of the test needs (a file written, a hit found):
 * when it fails, say so in the same form and stop the test. */
#define CHECK_REQUIRE(c, ok, ...)                                               \
  do {                                                                          \
    if (!(ok)) {                                                                \
      char check_what_[CHECK_TEXT];                                             \
      snprintf(check_what_, sizeof check_what_, __VA_ARGS__);                   \
      cr_assert(0, "%s: %s\n  read %s%s", (c)->fn, check_what_, (c)->doc,        \
                CHECK_RELIES_(c));                                              \
    }                                                                           \
  } while (0)

/* |got - expected| <= tol (equal infinities pass; NaN fails). */
#define CHECK_NEAR(c, expected, got, tol, ...)                                  \
  do {                                                                          \
    double check_e_ = (double)(expected), check_g_ = (double)(got);             \
    double check_t_ = (double)(tol);                                            \
    bool check_ok_ = check_g_ == check_e_ || fabs(check_g_ - check_e_) <= check_t_; \
    if (check_show_((c), check_ok_)) {                                          \
      char check_what_[CHECK_TEXT];                                             \
      snprintf(check_what_, sizeof check_what_, __VA_ARGS__);                   \
      char check_w_[48];                                                        \
      cr_expect(0, "%s: %s\n  expected %.9g%s\n  got      %.9g\n  read %s%s",   \
                (c)->fn, check_what_, check_e_,                                 \
                check_within_(check_w_, sizeof check_w_, check_t_), check_g_,   \
                (c)->doc, CHECK_RELIES_(c));                                    \
    }                                                                           \
  } while (0)

/* |got - expected| <= rel |expected|. */
#define CHECK_REL(c, expected, got, rel, ...)                                   \
  do {                                                                          \
    double check_e_ = (double)(expected), check_g_ = (double)(got);             \
    double check_r_ = (double)(rel);                                            \
    bool check_ok_ = check_g_ == check_e_ ||                                    \
                     fabs(check_g_ - check_e_) <= check_r_ * fabs(check_e_);    \
    if (check_show_((c), check_ok_)) {                                          \
      char check_what_[CHECK_TEXT];                                             \
      snprintf(check_what_, sizeof check_what_, __VA_ARGS__);                   \
      cr_expect(0, "%s: %s\n  expected %.9g (within %.2g relative)\n  got      %.9g " \
                   "(%.2g relative)\n  read %s%s",                              \
                (c)->fn, check_what_, check_e_, check_r_, check_g_,             \
                check_e_ != 0.0 ? fabs(check_g_ - check_e_) / fabs(check_e_) : INFINITY, \
                (c)->doc, CHECK_RELIES_(c));                                    \
    }                                                                           \
  } while (0)

/* got within max_ulps float ulps of expected (the last bits left free). */
#define CHECK_ULPS(c, expected, got, max_ulps, ...)                             \
  do {                                                                          \
    float check_e_ = (float)(expected), check_g_ = (float)(got);                \
    int64_t check_u_ = check_ulps(check_e_, check_g_);                          \
    if (check_show_((c), check_u_ <= (int64_t)(max_ulps))) {                    \
      char check_what_[CHECK_TEXT];                                             \
      snprintf(check_what_, sizeof check_what_, __VA_ARGS__);                   \
      cr_expect(0, "%s: %s\n  expected %.9g (within %d ulps)\n  got      %.9g (%lld ulps " \
                   "away)\n  read %s%s",                                        \
                (c)->fn, check_what_, (double)check_e_, (int)(max_ulps), (double)check_g_, \
                (long long)check_u_, (c)->doc, CHECK_RELIES_(c));               \
    }                                                                           \
  } while (0)

/* Each component of the vec3s got within tol of expected's. */
#define CHECK_VEC(c, expected, got, tol, ...)                                   \
  do {                                                                          \
    vec3s check_e_ = (expected), check_g_ = (got);                              \
    double check_t_ = (double)(tol);                                            \
    bool check_ok_ = true;                                                      \
    for (int check_k_ = 0; check_k_ < 3; check_k_++)                            \
      check_ok_ = check_ok_ && (check_g_.raw[check_k_] == check_e_.raw[check_k_] || \
                                fabs((double)check_g_.raw[check_k_] -           \
                                     check_e_.raw[check_k_]) <= check_t_);      \
    if (check_show_((c), check_ok_)) {                                          \
      char check_what_[CHECK_TEXT];                                             \
      snprintf(check_what_, sizeof check_what_, __VA_ARGS__);                   \
      char check_w_[48];                                                        \
      cr_expect(0, "%s: %s\n  expected (%.9g, %.9g, %.9g)%s\n  got      "       \
                   "(%.9g, %.9g, %.9g)\n  read %s%s",                           \
                (c)->fn, check_what_, (double)check_e_.x, (double)check_e_.y,   \
                (double)check_e_.z, check_within_(check_w_, sizeof check_w_, check_t_), \
                (double)check_g_.x, (double)check_g_.y, (double)check_g_.z,     \
                (c)->doc, CHECK_RELIES_(c));                                    \
    }                                                                           \
  } while (0)

/* Integers (counts, bytes, flags) equal. */
#define CHECK_INT(c, expected, got, ...)                                        \
  do {                                                                          \
    long long check_e_ = (long long)(expected), check_g_ = (long long)(got);    \
    if (check_show_((c), check_e_ == check_g_)) {                               \
      char check_what_[CHECK_TEXT];                                             \
      snprintf(check_what_, sizeof check_what_, __VA_ARGS__);                   \
      cr_expect(0, "%s: %s\n  expected %lld\n  got      %lld\n  read %s%s",     \
                (c)->fn, check_what_, check_e_, check_g_, (c)->doc, CHECK_RELIES_(c)); \
    }                                                                           \
  } while (0)

/* After a loop of cases: when more failed than were shown, say how many. */
#define CHECK_DONE(c)                                                           \
  do {                                                                          \
    if ((c)->failed > CHECK_SHOWN)                                              \
      cr_expect(0, "%s: %d of %d cases failed (the first %d are shown above)\n  read %s%s", \
                (c)->fn, (c)->failed, (c)->cases, CHECK_SHOWN, (c)->doc, "");   \
  } while (0)

#endif
