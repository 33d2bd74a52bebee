/* Unit tests of step 07's sampling patterns (common/sampler.c): one sample
 * per stratum (cells written out by hand), values in [0,1), the same key
 * gives the same samples, neighbouring pixels differ, the Sobol points form
 * (0,m,2)-nets, and the stochastic estimates are unbiased over seeds.
 * docs/07-antialiasing.md. */
#include "check.h"
#include "sampler.h"

#define DOC "docs/07-antialiasing.md, \"Samplers\""

static const SamplerKind STOCHASTIC[] = {SAMPLER_RANDOM, SAMPLER_JITTER, SAMPLER_SOBOL};

static vec2s get(SamplerKind kind, uint32_t seed, uint32_t pixel, uint32_t index,
                 uint32_t count)
{
  SamplerPattern p = sampler_pattern(kind, seed, pixel, count);
  return sampler_point(&p, index);
}

static bool in_box(vec2s s, double x0, double x1, double y0, double y1)
{
  return s.x >= x0 && s.x < x1 && s.y >= y0 && s.y < y1;
}

Test(sampler, names_round_trip)
{
  const char *names[] = {"center", "grid", "random", "jitter", "sobol"};
  Check c = CHECK("sampler_parse, sampler_name", DOC);
  for (int k = 0; k < 5; k++) {
    SamplerKind kind = SAMPLER_COUNT;
    bool ok = sampler_parse(names[k], &kind);
    CHECK_THAT(&c, ok && !strcmp(sampler_name(kind), names[k]),
               "'%s' parsed %s and named back '%s'", names[k], ok ? "ok" : "as unknown",
               ok ? sampler_name(kind) : "-");
  }
  SamplerKind kind;
  CHECK_INT(&c, 0, sampler_parse("halton", &kind), "'halton' is no sampler: parse result");
}

Test(sampler, center_puts_every_sample_at_the_pixel_centre)
{
  Check c = CHECK("sampler_point", DOC);
  for (uint32_t k = 0; k < 16; k++) {
    vec2s s = get(SAMPLER_CENTER, 7, 123, k, 16);
    CHECK_THAT(&c, s.x == 0.5f && s.y == 0.5f,
               "center, sample %u of 16: expected (0.5, 0.5), got (%.9g, %.9g)", k, s.x, s.y);
  }
  CHECK_DONE(&c);
}

Test(sampler, every_sample_lies_in_the_unit_square)
{
  /* Counts 1..70 (squares and not), the last index of the largest count, and
   * many pixels and seeds: never below 0, never 1 or more. */
  Check c = CHECK("sampler_point", DOC);
  for (int kind = 0; kind < SAMPLER_COUNT; kind++)
    for (uint32_t count = 1; count <= 70; count++)
      for (uint32_t pixel = 0; pixel < 40; pixel++)
        for (uint32_t k = 0; k < count; k++) {
          vec2s s = get((SamplerKind)kind, pixel * 7919u, pixel, k, count);
          CHECK_THAT(&c, in_box(s, 0.0, 1.0, 0.0, 1.0), "%s, sample %u of %u, pixel %u: "
                     "expected a point of [0,1)^2, got (%.9g, %.9g)",
                     sampler_name((SamplerKind)kind), k, count, pixel, s.x, s.y);
        }
  for (int kind = 0; kind < SAMPLER_COUNT; kind++) {
    vec2s s = get((SamplerKind)kind, 1, 5, 65535, 65536);
    CHECK_THAT(&c, in_box(s, 0.0, 1.0, 0.0, 1.0), "%s, sample 65535 of 65536: expected a "
               "point of [0,1)^2, got (%.9g, %.9g)", sampler_name((SamplerKind)kind), s.x, s.y);
  }
  CHECK_DONE(&c);
}

/* Grid and jitter with count = k^2: sample c lies in cell (c mod k, c div k)
 * of the k x k grid, at its centre for grid. */
Test(sampler, square_counts_put_one_sample_in_each_grid_cell)
{
  Check c = CHECK("sampler_point", DOC);
  for (uint32_t k = 1; k <= 9; k++)
    for (uint32_t cell = 0; cell < k * k; cell++) {
      double x0 = (double)(cell % k) / k, y0 = (double)(cell / k) / k, h = 1.0 / k;
      vec2s g = get(SAMPLER_GRID, 3, 11, cell, k * k);
      CHECK_THAT(&c, fabs(g.x - (x0 + h / 2)) < 1e-6 && fabs(g.y - (y0 + h / 2)) < 1e-6,
                 "grid %ux%u, sample %u: expected the centre of its cell (%.6g, %.6g), got "
                 "(%.9g, %.9g)", k, k, cell, x0 + h / 2, y0 + h / 2, g.x, g.y);
      for (uint32_t pixel = 0; pixel < 20; pixel++) {
        vec2s s = get(SAMPLER_JITTER, 3, pixel, cell, k * k);
        CHECK_THAT(&c, in_box(s, x0, x0 + h, y0, y0 + h), "jitter %ux%u, sample %u, pixel %u: "
                   "expected a point of [%.4g, %.4g) x [%.4g, %.4g), got (%.9g, %.9g)", k, k,
                   cell, pixel, x0, x0 + h, y0, y0 + h, s.x, s.y);
      }
    }
  CHECK_DONE(&c);
}

/* Other counts: r = floor(sqrt(n)) rows of equal-area cells (sampler.h). The
 * cells, worked out by hand:
 *   n = 2: r = 1, two cells 1/2 wide.    n = 3: r = 1, three cells 1/3 wide.
 *   n = 5: r = 2; row 0 holds floor(5/2) = 2 cells and is 2/5 tall, row 1
 *          holds 3 cells and is 3/5 tall.
 *   n = 7: r = 2; row 0: 3 cells, 3/7 tall; row 1: 4 cells, 4/7 tall.
 *   n = 8: r = 2; two rows of 4 cells, each 1/2 tall. */
typedef struct Cell {
  double x0, x1, y0, y1;
} Cell;

static const struct {
  uint32_t n;
  Cell cells[8];
} LAYOUTS[] = {
    {2, {{0, .5, 0, 1}, {.5, 1, 0, 1}}},
    {3, {{0, 1 / 3., 0, 1}, {1 / 3., 2 / 3., 0, 1}, {2 / 3., 1, 0, 1}}},
    {5, {{0, .5, 0, .4}, {.5, 1, 0, .4}, {0, 1 / 3., .4, 1}, {1 / 3., 2 / 3., .4, 1},
         {2 / 3., 1, .4, 1}}},
    {7, {{0, 1 / 3., 0, 3 / 7.}, {1 / 3., 2 / 3., 0, 3 / 7.}, {2 / 3., 1, 0, 3 / 7.},
         {0, .25, 3 / 7., 1}, {.25, .5, 3 / 7., 1}, {.5, .75, 3 / 7., 1},
         {.75, 1, 3 / 7., 1}}},
    {8, {{0, .25, 0, .5}, {.25, .5, 0, .5}, {.5, .75, 0, .5}, {.75, 1, 0, .5},
         {0, .25, .5, 1}, {.25, .5, .5, 1}, {.5, .75, .5, 1}, {.75, 1, .5, 1}}},
};

Test(sampler, other_counts_put_one_sample_in_each_equal_area_cell)
{
  Check c = CHECK("sampler_point", DOC);
  for (size_t l = 0; l < sizeof LAYOUTS / sizeof LAYOUTS[0]; l++) {
    uint32_t n = LAYOUTS[l].n;
    for (uint32_t cell = 0; cell < n; cell++) {
      Cell b = LAYOUTS[l].cells[cell];
      vec2s g = get(SAMPLER_GRID, 1, 0, cell, n);
      CHECK_THAT(&c, fabs(g.x - (b.x0 + b.x1) / 2) < 1e-6 && fabs(g.y - (b.y0 + b.y1) / 2) < 1e-6,
                 "grid, %u samples, sample %u: expected the centre of [%.4g, %.4g) x "
                 "[%.4g, %.4g), got (%.9g, %.9g)", n, cell, b.x0, b.x1, b.y0, b.y1, g.x, g.y);
      for (uint32_t pixel = 0; pixel < 50; pixel++) {
        vec2s s = get(SAMPLER_JITTER, 9, pixel, cell, n);
        CHECK_THAT(&c, in_box(s, b.x0, b.x1, b.y0, b.y1), "jitter, %u samples, sample %u, "
                   "pixel %u: expected a point of [%.4g, %.4g) x [%.4g, %.4g), got "
                   "(%.9g, %.9g)", n, cell, pixel, b.x0, b.x1, b.y0, b.y1, s.x, s.y);
      }
    }
  }
  CHECK_DONE(&c);
}

Test(sampler, the_same_key_gives_the_same_samples)
{
  Check c = CHECK("sampler_point", DOC);
  for (size_t s = 0; s < 3; s++)
    for (uint32_t k = 0; k < 64; k++) {
      vec2s a = get(STOCHASTIC[s], 42, 1000, k, 64), b = get(STOCHASTIC[s], 42, 1000, k, 64);
      CHECK_THAT(&c, a.x == b.x && a.y == b.y, "%s, seed 42, pixel 1000, sample %u asked "
                 "twice: (%.9g, %.9g) then (%.9g, %.9g)", sampler_name(STOCHASTIC[s]), k, a.x,
                 a.y, b.x, b.y);
      vec2s g = sampler_get(STOCHASTIC[s], 42, 1000, k, 64);
      CHECK_THAT(&c, a.x == g.x && a.y == g.y, "%s, sample %u: sampler_get (%.9g, %.9g) and "
                 "sampler_point (%.9g, %.9g) differ", sampler_name(STOCHASTIC[s]), k, g.x, g.y,
                 a.x, a.y);
    }
  CHECK_DONE(&c);
}

/* Neighbouring pixels (and other seeds) get other points: with 24-bit
 * coordinates, equal first samples would be a 2^-48 coincidence per pair. */
Test(sampler, neighbouring_pixels_and_other_seeds_differ)
{
  Check c = CHECK("sampler_point", DOC);
  for (size_t s = 0; s < 3; s++)
    for (uint32_t p = 0; p < 200; p++) {
      vec2s a = get(STOCHASTIC[s], 1, p, 0, 16), b = get(STOCHASTIC[s], 1, p + 1, 0, 16);
      vec2s d = get(STOCHASTIC[s], 2, p, 0, 16);
      CHECK_THAT(&c, a.x != b.x || a.y != b.y, "%s: pixels %u and %u got the same sample 0 "
                 "(%.9g, %.9g): the pattern must be keyed by the pixel",
                 sampler_name(STOCHASTIC[s]), p, p + 1, a.x, a.y);
      CHECK_THAT(&c, a.x != d.x || a.y != d.y, "%s, pixel %u: seeds 1 and 2 got the same "
                 "sample 0 (%.9g, %.9g)", sampler_name(STOCHASTIC[s]), p, a.x, a.y);
    }
  CHECK_DONE(&c);
}

/* The first 2^m Sobol points form a (0,m,2)-net: every box
 * [i/2^a, (i+1)/2^a) x [j/2^b, (j+1)/2^b) with a + b = m holds exactly one
 * point, for each pixel's scramble (Owen scrambling keeps nets). */
Test(sampler, sobol_points_form_a_net_in_every_pixel)
{
  static int hits[4096];
  Check c = CHECK("sampler_point", DOC);
  for (uint32_t pixel = 0; pixel < 12; pixel++)
    for (int m = 0; m <= 12; m++) {
      uint32_t n = 1u << m;
      for (int a = 0; a <= m; a++) {
        int b = m - a;
        memset(hits, 0, sizeof hits);
        SamplerPattern p = sampler_pattern(SAMPLER_SOBOL, 5, pixel, n);
        for (uint32_t k = 0; k < n; k++) {
          vec2s s = sampler_point(&p, k);
          uint32_t i = (uint32_t)floor(s.x * (double)(1u << a));
          uint32_t j = (uint32_t)floor(s.y * (double)(1u << b));
          hits[j << a | i]++;
        }
        int bad = 0;
        for (uint32_t k = 0; k < n; k++)
          bad += hits[k] != 1;
        CHECK_INT(&c, 0, bad, "sobol, pixel %u, the first 2^%d points, boxes 2^-%d x 2^-%d: "
                  "boxes holding other than one point", pixel, m, a, b);
      }
    }
  CHECK_DONE(&c);
}

/* Estimate of the area of the quarter disc x^2 + y^2 < 0.8 (exactly
 * 0.2 pi = 0.6283185...) from n samples of one pixel. */
static double disc_estimate(SamplerKind kind, uint32_t seed, uint32_t pixel, uint32_t n)
{
  int inside = 0;
  for (uint32_t k = 0; k < n; k++) {
    vec2s s = get(kind, seed, pixel, k, n);
    inside += (double)s.x * s.x + (double)s.y * s.y < 0.8;
  }
  return (double)inside / n;
}

/* Mean and variance of the estimates over `reps` seeds. */
static void over_seeds(SamplerKind kind, uint32_t n, int reps, double *mean, double *var)
{
  double sum = 0.0, sum2 = 0.0;
  for (int r = 0; r < reps; r++) {
    double e = disc_estimate(kind, (uint32_t)r + 1, 77, n);
    sum += e;
    sum2 += e * e;
  }
  *mean = sum / reps;
  *var = (sum2 - sum * sum / reps) / (reps - 1);
}

/* Unbiased: over 64 seeds the mean estimate lies within 4 standard errors of
 * the exact area (the standard error measured from the 64 estimates). */
Test(sampler, stochastic_samplers_are_unbiased_over_seeds)
{
  const double exact = 0.2 * 3.14159265358979323846;
  const uint32_t counts[] = {4, 16, 64};
  Check c = CHECK("sampler_point", DOC);
  for (size_t s = 0; s < 3; s++)
    for (size_t n = 0; n < 3; n++) {
      double mean, var;
      over_seeds(STOCHASTIC[s], counts[n], 64, &mean, &var);
      double se = sqrt(var / 64);
      CHECK_THAT(&c, se > 0.0, "%s, %u samples: the estimate is the same for 64 seeds",
                 sampler_name(STOCHASTIC[s]), counts[n]);
      CHECK_NEAR(&c, exact, mean, 4.0 * se, "%s, %u samples: mean over 64 seeds of the "
                 "fraction inside a quarter disc (4 standard errors)",
                 sampler_name(STOCHASTIC[s]), counts[n]);
    }
  CHECK_DONE(&c);
}

/* Random sampling is Bernoulli: the estimate's variance is p(1-p)/n. Over 256
 * seeds the sample variance lies within [0.65, 1.35] of it (the chi-square
 * bounds with 255 degrees of freedom at about 4 standard deviations).
 * Stratified patterns must do clearly better on the same edge. */
Test(sampler, random_has_binomial_variance_and_stratified_patterns_less)
{
  const double p = 0.2 * 3.14159265358979323846;
  const uint32_t n = 16;
  double mean, var_random, var_jitter, var_sobol;
  over_seeds(SAMPLER_RANDOM, n, 256, &mean, &var_random);
  over_seeds(SAMPLER_JITTER, n, 256, &mean, &var_jitter);
  over_seeds(SAMPLER_SOBOL, n, 256, &mean, &var_sobol);
  double binomial = p * (1.0 - p) / n;
  Check c = CHECK("sampler_point", DOC);
  CHECK_REL(&c, binomial, var_random, 0.35, "random, 16 samples: variance over 256 seeds "
            "against p(1-p)/n");
  CHECK_THAT(&c, var_jitter < 0.5 * binomial, "jitter, 16 samples: variance %.5f, expected "
             "under half of random's %.5f (stratified)", var_jitter, binomial);
  CHECK_THAT(&c, var_sobol < 0.5 * binomial, "sobol, 16 samples: variance %.5f, expected "
             "under half of random's %.5f (stratified)", var_sobol, binomial);
}
