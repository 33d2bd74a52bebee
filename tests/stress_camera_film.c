/* Stress tests 6-8 of docs/accuracy.md: the camera basis when up nearly
 * equals the view direction, long sums in the film, the random number
 * generator's range and the sRGB round trip; references in long double. */
#include "check.h"

#include "camera.h"
#include "film.h"
#include "app/image.h"
#include "stress.h"

static long double ldot(vec3s a, vec3s b)
{
  return (long double)a.x * b.x + (long double)a.y * b.y + (long double)a.z * b.z;
}

/* Largest deviation of (u, v, w) from an orthonormal basis (NaN if any). */
static double basis_error(vec3s u, vec3s v, vec3s w)
{
  long double e = 0.0L;
  const vec3s *b[3] = {&u, &v, &w};
  for (int i = 0; i < 3; i++)
    for (int j = i; j < 3; j++) {
      long double d = fabsl(ldot(*b[i], *b[j]) - (i == j ? 1.0L : 0.0L));
      e = isnan(d) || d > e ? d : e;
    }
  return (double)e;
}

/* The textbook lookAt basis, for comparison: float cross products, each
 * normalized by dividing by its length, no re-orthogonalization. */
static double textbook_basis_error(vec3s eye, vec3s center, vec3s up)
{
  vec3s w = glms_vec3_sub(eye, center);
  w = glms_vec3_scale(w, 1.0f / glms_vec3_norm(w));
  vec3s u = glms_vec3_cross(up, w);
  u = glms_vec3_scale(u, 1.0f / glms_vec3_norm(u));
  return basis_error(u, glms_vec3_cross(w, u), w);
}

/* `dir` turned by `angle` radians about an axis perpendicular to it. */
static vec3s turned(vec3s dir, vec3s axis_perp, double angle)
{
  double c = cos(angle), s = sin(angle);
  return vec_make((float)(c * dir.x + s * axis_perp.x), (float)(c * dir.y + s * axis_perp.y),
                  (float)(c * dir.z + s * axis_perp.z));
}

Test(stress, t6_camera_basis_orthonormal_when_up_is_almost_the_view_direction)
{
  stress_step(3);
  stress_table("t6_camera", "Test 6: camera basis, worst |u.v|, ||u|-1|, ... (and w against "
               "the exact view direction) for up within angle of the view direction",
               "| angle (rad) | cameras | textbook orthonormality | orthonormality | w error |"
               "\n|---|---|---|---|---|");
  const double angles[] = {1e-6, 1e-7, 1e-9, 0.0};
  const char *labels[] = {"1e-6", "1e-7", "1e-9", "0 (exactly parallel: fallback)"};
  double worst = 0.0;
  Check ck = CHECK("camera_init (step 03)", "docs/03-camera.md, \"What you write\"");
  Check rk = CHECK_RELYING("camera_ray (step 03)", "docs/03-camera.md, \"What you write\"",
                           "camera_init (its basis)");
  for (int a = 0; a < 4; a++) {
    double w_orth = 0.0, w_dir = 0.0, w_txt = 0.0;
    for (int k = 0; k < 5000; k++) {
      Rng g = rng_make(6, (uint32_t)a, (uint32_t)k);
      vec3s eye = glms_vec3_scale(stress_unit(&g), (float)stress_log10u(&g, -3.0, 5.0));
      vec3s view = stress_unit(&g);
      vec3s center = glms_vec3_add(eye, glms_vec3_scale(view, (float)stress_log10u(&g, -2.0, 4.0)));
      vec3s up = turned(view, stress_perp(view, &g), angles[a]);
      if (k % 2)
        up = glms_vec3_scale(up, -1.0f); /* up opposite to the view direction */
      Camera cam;
      camera_init(&cam, eye, center, up, 40.0f, 1.0f, 1.5f);
      w_orth = fmax(w_orth, basis_error(cam.u, cam.v, cam.w));
      double e_txt = textbook_basis_error(eye, center, up);
      w_txt = isnan(e_txt) || e_txt > w_txt ? e_txt : w_txt;
      /* w = (eye - center) / |eye - center|, the difference taken in long double. */
      long double dx = (long double)eye.x - center.x, dy = (long double)eye.y - center.y,
                  dz = (long double)eye.z - center.z, n = sqrtl(dx * dx + dy * dy + dz * dz);
      w_dir = fmax(w_dir, (double)fmaxl(fabsl(cam.w.x - dx / n),
                                        fmaxl(fabsl(cam.w.y - dy / n), fabsl(cam.w.z - dz / n))));
      float x = rng_float(&g), y = rng_float(&g);
      Ray r = camera_ray(&cam, x, y);
      CHECK_THAT(&rk, vec_is_finite(r.d) && vec_is_finite(r.o), "camera %d with up %s rad "
                 "from the view direction: the ray is not finite, d = (%g, %g, %g)", k,
                 labels[a], r.d.x, r.d.y, r.d.z);
    }
    stress_row("t6_camera", "| %s | 5000 | %.2e | %.2e | %.2e |", labels[a], w_txt, w_orth, w_dir);
    worst = fmax(worst, fmax(w_orth, w_dir));
    CHECK_THAT(&ck, w_orth <= 1e-6 && w_dir <= 1e-6, "5000 cameras with up %s rad from the "
               "view direction: the basis is off by %.2e (orthonormality) and %.2e (w against "
               "the exact view direction); at most 1e-6 asked: compute u = normalize(up x w) "
               "and v = w x u in double (a float cross product of nearly parallel vectors "
               "keeps few bits), and when up is parallel take the world axis least aligned "
               "with w", labels[a], w_orth, w_dir);
  }
  CHECK_DONE(&ck);
  CHECK_DONE(&rk);
  cr_log_info("test 6: worst camera basis error %.2e", worst);
}

/* Exact mean of n copies of the floats produced by `next` (long double sum:
 * 64-bit significand, 2^26 terms of 24 bits lose nothing that matters). */
Test(stress, t7_film_average_of_2_24_and_more_samples_within_1e_6)
{
  stress_step(7);
  stress_table("t7_film_sum", "Test 7: mean of n samples, relative error against a long "
               "double sum", "| samples | values | naive float sum | FilmAccum (Neumaier) |"
               "\n|---|---|---|---|");
  const unsigned counts[] = {1u << 24, 1u << 25, 3u << 24};
  double worst = 0.0;
  for (int c = 0; c < 3; c++) {
    for (int kind = 0; kind < 2; kind++) {
      FilmAccum acc = {0};
      float naive = 0.0f;
      long double exact = 0.0L;
      Rng g = rng_make(7, (uint32_t)c, (uint32_t)kind);
      for (unsigned k = 0; k < counts[c]; k++) {
        float x = kind ? rng_float(&g) : 0.1f;
        film_accum_add(&acc, vec_make(x, x, x));
        naive += x;
        exact += x;
      }
      long double mean = exact / counts[c];
      double e_acc = (double)fabsl(film_accum_mean(&acc).g - mean) / (double)mean;
      double e_naive = (double)fabsl(naive / (float)counts[c] - mean) / (double)mean;
      stress_row("t7_film_sum", "| %u | %s | %.2e | %.2e |", counts[c],
                 kind ? "uniform [0, 1)" : "0.1 each", e_naive, e_acc);
      worst = fmax(worst, e_acc);
    }
  }
  cr_log_info("test 7: worst relative error of the mean %.2e", worst);
  Check c = CHECK("film_accum_mean (given code)", "docs/07-antialiasing.md, \"The math\"");
  CHECK_NEAR(&c, 0.0, worst, 1e-6, "mean of 2^24 .. 3 x 2^24 samples: worst relative error");
}

/* Inverse of splitmix64's finalizer rng_mix (xorshifts and odd multipliers
 * are invertible): the state whose output is all ones. */
static uint64_t unxorshift(uint64_t y, int s)
{
  uint64_t x = y;
  for (int k = 0; k < 64 / s + 1; k++)
    x = y ^ (x >> s);
  return x;
}

static uint64_t inverse_odd(uint64_t a)
{
  uint64_t x = a; /* Newton: x = x (2 - a x) doubles the correct bits */
  for (int k = 0; k < 6; k++)
    x *= 2 - a * x;
  return x;
}

Test(stress, t8_rng_never_returns_one_and_srgb_round_trips_all_codes)
{
  stress_step(1);
  uint64_t y = ~0ull;
  y = unxorshift(y, 31);
  y *= inverse_odd(0x94d049bb133111ebull);
  y = unxorshift(y, 27);
  y *= inverse_odd(0xbf58476d1ce4e5b9ull);
  y = unxorshift(y, 30);
  cr_assert(rng_mix(y) == ~0ull, "the test's own inverse of rng_mix is wrong");
  Rng r = {y - 0x9e3779b97f4a7c15ull}; /* rng_next adds the increment first */
  float top = rng_float(&r);
  Check rc = CHECK("rng_float (given code)", "docs/07-antialiasing.md, \"The math\"");
  CHECK_NEAR(&rc, 1.0 - 0x1p-24, top, 0.0, "rng_float for all-ones bits: the largest output, "
             "below 1");
  Check c = CHECK("film_to_byte (step 01)", "docs/01-film.md, \"What you write\"");
  int bad = 0;
  for (int b = 0; b < 256; b++) {
    /* The exact sRGB decoding of code b, in long double. */
    long double v = b / 255.0L;
    long double lin = v <= 0.04045L ? v / 12.92L : powl((v + 0.055L) / 1.055L, 2.4L);
    int back = film_to_byte((float)lin, TONEMAP_SRGB);
    bad += back != b;
    CHECK_INT(&c, b, back, "srgb tone map of %.9g, the exact linear value of sRGB code %d: "
              "the code back", (double)lin, b);
  }
  CHECK_DONE(&c);
  stress_table("t8_rng_srgb", "Test 8: random numbers and sRGB export",
               "| check | result |\n|---|---|");
  stress_row("t8_rng_srgb", "| largest rng_float (all-ones bits) | 1 - 2^-24 = %a |", top);
  stress_row("t8_rng_srgb", "| sRGB codes not round-tripping (of 256) | %d |", bad);
}
