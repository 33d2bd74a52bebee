/* Film: linear float RGB pixels, the lecture's sample positions, export
 * (step 01). docs/01-film.md. */
#include "film.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

bool film_init(Film *film, int width, int height)
{
  film->width = width;
  film->height = height;
  film->memo = NULL;
  film->rgb = calloc((size_t)width * height * 3, sizeof(float));
  if (!film->rgb) {
    fprintf(stderr, "film: out of memory for %dx%d pixels\n", width, height);
    film->width = film->height = 0;
    return false;
  }
  return true;
}

void film_free(Film *film)
{
  free(film->rgb);
  film->rgb = NULL;
  film->width = film->height = 0;
}

vec2s film_sample(const Film *film, int i, int j)
{
  /* BEGIN SOLUTION step 01 */
  vec2s s = {.x = ((float)i + 0.5f) / (float)film->width,
             .y = ((float)j + 0.5f) / (float)film->height};
  return s;
  /* STUB: return (vec2s){.x = 0.0f, .y = 0.0f}; */
  /* END SOLUTION */
}

void film_set(Film *film, int i, int j, vec3s c)
{
  float *px = film->rgb + 3 * ((size_t)j * film->width + i);
  px[0] = c.r;
  px[1] = c.g;
  px[2] = c.b;
}

vec3s film_get(const Film *film, int i, int j)
{
  const float *px = film->rgb + 3 * ((size_t)j * film->width + i);
  return vec_make(px[0], px[1], px[2]);
}

/* The sRGB transfer curve (IEC 61966-2-1) for linear c in [0, 1]. */
static float srgb_encode(float c)
{
  return c <= 0.0031308f ? 12.92f * c : 1.055f * powf(c, 1.0f / 2.4f) - 0.055f;
}

unsigned char film_to_byte(float c, Tonemap tm)
{
  /* BEGIN SOLUTION step 01 */
  if (!(c > 0.0f)) /* also maps NaN to 0 */
    return 0;
  if (tm == TONEMAP_REINHARD) /* infinity would give inf/inf = NaN: its limit is 1 */
    c = isinf(c) ? 1.0f : c / (1.0f + c);
  if (c > 1.0f)
    c = 1.0f;
  if (tm != TONEMAP_CLAMP)
    c = srgb_encode(c);
  /* Round to nearest: the lecture truncates, which darkens by half a code.
   * Halves round up, as round() does; written out because roundf is a libm
   * call per channel. k = trunc(x), and x - k is exact (Sterbenz). */
  float x = 255.0f * c;
  int k = (int)x;
  return (unsigned char)(k + (x - (float)k >= 0.5f));
  /* STUB: return 0; */
  /* END SOLUTION */
}


/* A float-float sum per channel: TwoSum (Knuth) gives the exact rounding
 * error of each addition, it is added to `comp`, and (sum, comp) is then
 * renormalized so that comp stays under half an ulp of sum. Plain Neumaier
 * (comp summed naively) loses float precision after ~10^4 samples, since
 * comp's own rounding then grows with n^2 eps^2. */
static void accum1(float *sum, float *comp, float x)
{
  float s = *sum + x;
  if (!isfinite(s)) { /* an overflowing sum stays infinite (inf - inf would be NaN) */
    *sum = s;
    *comp = 0.0f;
    return;
  }
  float bp = s - *sum;
  float e = (*sum - (s - bp)) + (x - bp); /* s + e == sum + x exactly */
  float c = *comp + e;
  float t = s + c; /* FastTwoSum: |s| >= |c| */
  *comp = c - (t - s);
  *sum = t;
}

void film_accum_add(FilmAccum *acc, vec3s c)
{
  accum1(&acc->sum.r, &acc->comp.r, c.r);
  accum1(&acc->sum.g, &acc->comp.g, c.g);
  accum1(&acc->sum.b, &acc->comp.b, c.b);
  acc->n++;
}

vec3s film_accum_mean(const FilmAccum *acc)
{
  if (acc->n == 0)
    return glms_vec3_zero();
  return glms_vec3_divs(glms_vec3_add(acc->sum, acc->comp), (float)acc->n);
}
