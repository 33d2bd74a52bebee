/* Unit tests of the film (step 01): the lecture's sample positions, pixel
 * storage (j from the bottom) and the compensated mean of many samples.
 * docs/01-film.md. */
#include "check.h"

#include "film.h"
#include "scene.h"

#define DOC "docs/01-film.md, \"What you write\""

Test(film, sample_is_the_pixel_centre_over_the_film_size)
{
  Film f;
  cr_assert(film_init(&f, 4, 2), "film_init (given code): out of memory");
  /* ((i + 0.5) / w, (j + 0.5) / h): all exact in binary. */
  const struct {
    int i, j;
    float x, y;
  } cases[] = {{0, 0, 0.125f, 0.25f}, {3, 1, 0.875f, 0.75f}, {2, 0, 0.625f, 0.25f}};
  Check c = CHECK("film_sample", DOC);
  for (int k = 0; k < 3; k++) {
    vec2s s = film_sample(&f, cases[k].i, cases[k].j);
    CHECK_NEAR(&c, cases[k].x, s.x, 0.0, "film 4 x 2, pixel (%d, %d): x = (i + 0.5) / 4",
               cases[k].i, cases[k].j);
    CHECK_NEAR(&c, cases[k].y, s.y, 0.0, "film 4 x 2, pixel (%d, %d): y = (j + 0.5) / 2 "
               "(j counts from the bottom)", cases[k].i, cases[k].j);
  }
  film_free(&f);
}

Test(film, sample_of_an_odd_size_is_within_an_ulp)
{
  Film f;
  cr_assert(film_init(&f, 3, 7), "film_init (given code): out of memory");
  /* (i + 0.5) / w: one division of exact values, so within half an ulp of the
   * exact fraction; 1 ulp leaves the order of operations free. */
  Check c = CHECK("film_sample", DOC);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 7; j++) {
      vec2s s = film_sample(&f, i, j);
      CHECK_ULPS(&c, (float)((i + 0.5L) / 3.0L), s.x, 1, "film 3 x 7, pixel (%d, %d): "
                 "x = (i + 0.5) / 3", i, j);
      CHECK_ULPS(&c, (float)((j + 0.5L) / 7.0L), s.y, 1, "film 3 x 7, pixel (%d, %d): "
                 "y = (j + 0.5) / 7", i, j);
    }
  CHECK_DONE(&c);
  film_free(&f);
}

Test(film, starts_black_and_stores_rows_from_the_bottom)
{
  Film f;
  cr_assert(film_init(&f, 5, 3), "film_init (given code): out of memory");
  Check c = CHECK("film_init", "docs/01-film.md, \"The math\"");
  for (int k = 0; k < 5 * 3 * 3; k++)
    CHECK_NEAR(&c, 0.0, f.rgb[k], 0.0, "a new 5 x 3 film: float %d is black", k);
  CHECK_DONE(&c);
  Check s = CHECK("film_set, film_get", "docs/01-film.md, \"The math\"");
  film_set(&f, 3, 1, vec_make(0.25f, 0.5f, 0.75f));
  /* Row j = 1 starts at pixel 1 * 5; pixel (3, 1) is the 8th, floats 24..26. */
  CHECK_VEC(&s, vec_make(0.25f, 0.5f, 0.75f), vec_make(f.rgb[24], f.rgb[25], f.rgb[26]), 0.0,
            "film_set(3, 1) on a 5 x 3 film: floats 24..26 (row j = 1 first after row 0)");
  CHECK_VEC(&s, vec_make(0.25f, 0.5f, 0.75f), film_get(&f, 3, 1), 0.0, "film_get(3, 1)");
  int nonzero = 0;
  for (int k = 0; k < 5 * 3 * 3; k++)
    nonzero += f.rgb[k] != 0.0f;
  CHECK_INT(&s, 3, nonzero, "channels film_set changed");
  film_free(&f);
  Check fr = CHECK("film_free", "docs/01-film.md, \"The math\"");
  CHECK_THAT(&fr, f.rgb == NULL && f.width == 0 && f.height == 0,
             "after film_free: rgb NULL and size 0 x 0, got %p and %d x %d", (void *)f.rgb,
             f.width, f.height);
  film_free(&f); /* a second call is harmless */
}

Test(film, accum_mean_of_a_constant_is_exact)
{
  /* 65536 copies of 0.1f (the most samples a pixel takes): a plain float sum
   * is then 6e-4 too high (its ulp reaches 2^-11 while 0.1f's low bits
   * are rounded away each time), the compensated one gives 0.1f back. */
  FilmAccum acc = {0};
  const unsigned n = SCENE_MAX_SAMPLES;
  for (unsigned k = 0; k < n; k++)
    film_accum_add(&acc, vec_make(0.1f, 1.0f, 3.0f));
  vec3s m = film_accum_mean(&acc);
  Check c = CHECK("film_accum_mean", "docs/07-antialiasing.md, \"The math\"");
  CHECK_INT(&c, n, acc.n, "samples counted after %u film_accum_add", n);
  CHECK_ULPS(&c, 0.1f, m.x, 2, "mean of %u copies of 0.1", n);
  CHECK_NEAR(&c, 1.0, m.y, 0.0, "mean of %u copies of 1", n);
  CHECK_NEAR(&c, 3.0, m.z, 0.0, "mean of %u copies of 3", n);
}

Test(film, accum_mean_of_varying_samples_matches_long_double)
{
  FilmAccum acc = {0};
  long double sum[3] = {0};
  const unsigned n = 1000000;
  for (unsigned k = 0; k < n; k++) {
    /* Values of very different sizes, some negative. */
    float a = (float)(k % 1000) / 1000.0f, b = (k % 7 == 0) ? 1000.0f : 1e-3f * (float)(k % 13);
    float c = (k & 1) ? 0.3f : -0.1f;
    film_accum_add(&acc, vec_make(a, b, c));
    sum[0] += a;
    sum[1] += b;
    sum[2] += c;
  }
  vec3s m = film_accum_mean(&acc);
  Check c = CHECK("film_accum_mean", "docs/07-antialiasing.md, \"The math\"");
  /* One rounding of the sum plus the division: a few float ulps. */
  for (int ch = 0; ch < 3; ch++)
    CHECK_REL(&c, (double)(sum[ch] / n), m.raw[ch], 3.0 * 0x1p-24,
              "mean of 10^6 samples of mixed sizes, channel %d, against a long double sum", ch);
}

Test(film, accum_mean_of_nothing_is_zero)
{
  FilmAccum acc = {0};
  Check c = CHECK("film_accum_mean", "docs/07-antialiasing.md, \"The math\"");
  CHECK_VEC(&c, vec_make(0, 0, 0), film_accum_mean(&acc), 0.0, "mean of no samples");
}
