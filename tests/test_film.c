/* Unit tests of the film (step 01): the lecture's sample positions, pixel
 * storage (j from the bottom) and the compensated mean of many samples.
 * docs/01-film.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "film.h"
#include "scene.h"

Test(film, sample_is_the_pixel_centre_over_the_film_size)
{
  Film f;
  cr_assert(film_init(&f, 4, 2));
  /* ((i + 0.5) / w, (j + 0.5) / h): all exact in binary. */
  vec2s s = film_sample(&f, 0, 0);
  cr_expect(s.x == 0.125f && s.y == 0.25f, "(0,0) -> (%g, %g)", s.x, s.y);
  s = film_sample(&f, 3, 1);
  cr_expect(s.x == 0.875f && s.y == 0.75f, "(3,1) -> (%g, %g)", s.x, s.y);
  s = film_sample(&f, 2, 0);
  cr_expect(s.x == 0.625f && s.y == 0.25f, "(2,0) -> (%g, %g)", s.x, s.y);
  film_free(&f);
}

Test(film, sample_of_an_odd_size_is_correctly_rounded)
{
  Film f;
  cr_assert(film_init(&f, 3, 7));
  /* (i + 0.5) and the size are exact, so one correctly rounded division:
   * the float nearest to the exact fraction. */
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 7; j++) {
      vec2s s = film_sample(&f, i, j);
      cr_expect(s.x == (float)((i + 0.5L) / 3.0L), "x of (%d,%d) = %a", i, j, s.x);
      cr_expect(s.y == (float)((j + 0.5L) / 7.0L), "y of (%d,%d) = %a", i, j, s.y);
    }
  film_free(&f);
}

Test(film, starts_black_and_stores_rows_from_the_bottom)
{
  Film f;
  cr_assert(film_init(&f, 5, 3));
  for (int k = 0; k < 5 * 3 * 3; k++)
    cr_assert(f.rgb[k] == 0.0f, "channel %d not black", k);
  film_set(&f, 3, 1, vec_make(0.25f, 0.5f, 0.75f));
  /* Row j = 1 starts at pixel 1 * 5; pixel (3, 1) is the 8th, floats 24..26. */
  cr_expect(f.rgb[24] == 0.25f && f.rgb[25] == 0.5f && f.rgb[26] == 0.75f);
  vec3s c = film_get(&f, 3, 1);
  cr_expect(c.x == 0.25f && c.y == 0.5f && c.z == 0.75f);
  int nonzero = 0;
  for (int k = 0; k < 5 * 3 * 3; k++)
    nonzero += f.rgb[k] != 0.0f;
  cr_expect(nonzero == 3, "film_set touched %d channels, expected 3", nonzero);
  film_free(&f);
  cr_expect(f.rgb == NULL && f.width == 0 && f.height == 0);
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
  cr_expect(acc.n == n);
  cr_expect(fabsf(m.x - 0.1f) <= 0x1p-24f * 0.1f * 2.0f, "mean %a, expected %a", m.x, 0.1f);
  cr_expect(m.y == 1.0f, "mean %a", m.y);
  cr_expect(m.z == 3.0f, "mean %a", m.z);
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
  for (int ch = 0; ch < 3; ch++) {
    long double exact = sum[ch] / n;
    /* One rounding of the sum plus the division: a few float ulps. */
    long double err = fabsl(m.raw[ch] - exact) / fabsl(exact);
    cr_expect(err <= 3.0L * 0x1p-24L, "channel %d: mean %.9g, exact %.12Lg (rel %Lg)",
              ch, m.raw[ch], exact, err);
  }
}

Test(film, accum_mean_of_nothing_is_zero)
{
  FilmAccum acc = {0};
  vec3s m = film_accum_mean(&acc);
  cr_expect(m.x == 0.0f && m.y == 0.0f && m.z == 0.0f);
}
