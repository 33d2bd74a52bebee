/* Unit tests of the project's normalization (common/vec.h, used from step 02
 * on: plane normals, light directions, the view direction of step 04):
 * v / |v| against long double at every length a float can hold, whatever
 * cglm's version. docs/accuracy.md, "What the code does, and why". */
#include "check.h"

#define DOC "docs/accuracy.md, \"What the code does, and why\""

/* v * (1 / sqrt(v.v)): the sum of squares is off by at most 3 x 2^-24
 * (relative; half of that after the square root), and the square root, the
 * reciprocal and the product round once each: each component is within
 * 4.5 x 2^-24 of v_k / |v|, 5 ulps of its rounding (2 x 10^6 random vectors
 * of lengths 1e-40 .. 1e36 came within 3). */
enum { NORM_ULPS = 5 };

/* Directions with a zero, equal, small and large components (a plane normal,
 * the canonical scene's light, a 3-4-12 triangle, ...). */
static const float DIRS[][3] = {{1, 0, 0},   {0, -1, -0.5f}, {-1, -2, -1},      {1, -2, 2},
                                {3, 4, 12},  {0.3f, -0.7f, 0.2f}, {1e-3f, 1, -7}, {-5, 1e-4f, 0}};
/* Lengths around each edge: cglm 0.9's FLT_EPSILON cut-off (1.2e-7), the
 * scene format's 1e-18 and 1e18, squares that leave float's normal range
 * (1e-20, 1e20) and components that are subnormal (1e-40) or near the largest
 * float (1e37). */
static const float SCALES[] = {1e-40f, 1e-30f, 1e-20f, 1e-18f, 1e-12f, 1e-8f, 1.1e-7f,
                               1e-3f,  1.0f,   1e8f,   1e18f,  1e20f,  1e30f, 1e37f};

/* The exact unit vector along the float vector v, rounded once. */
static vec3s unit_ld(vec3s v)
{
  long double x = v.x, y = v.y, z = v.z, n = sqrtl(x * x + y * y + z * z);
  return vec_make((float)(x / n), (float)(y / n), (float)(z / n));
}

Test(vec, normalize_is_exact_at_every_length)
{
  Check c = CHECK("vec_normalize", DOC);
  for (size_t d = 0; d < sizeof DIRS / sizeof DIRS[0]; d++)
    for (size_t s = 0; s < sizeof SCALES / sizeof SCALES[0]; s++) {
      vec3s v = glms_vec3_scale(vec_make(DIRS[d][0], DIRS[d][1], DIRS[d][2]), SCALES[s]);
      vec3s want = unit_ld(v), got = vec_normalize(v);
      for (int k = 0; k < 3; k++)
        CHECK_ULPS(&c, want.raw[k], got.raw[k], NORM_ULPS,
                   "(%g, %g, %g) times %g: component %d of v / |v|", (double)DIRS[d][0],
                   (double)DIRS[d][1], (double)DIRS[d][2], (double)SCALES[s], k);
    }
  CHECK_DONE(&c);
}

Test(vec, normalize_of_zero_is_zero)
{
  Check c = CHECK("vec_normalize", DOC);
  CHECK_VEC(&c, vec_make(0, 0, 0), vec_normalize(vec_make(0, 0, 0)), 0.0,
            "the zero vector (no direction): (0, 0, 0), not NaN");
  CHECK_VEC(&c, vec_make(0, 0, 0), vec_normalize(vec_make(-0.0f, 0, -0.0f)), 0.0,
            "(-0, 0, -0): (0, 0, 0)");
}

/* The steps' code, the solution regions included, writes cglm's name:
 * common/vec.h makes it the project's function, so a student's call does not
 * depend on cglm's version either. */
Test(vec, glms_vec3_normalize_is_the_projects)
{
  Check c = CHECK("glms_vec3_normalize (common/vec.h)", DOC);
  const float lengths[] = {1e-18f, 1e-8f, 1e-7f, 1.0f, 1e18f};
  for (size_t s = 0; s < sizeof lengths / sizeof lengths[0]; s++) {
    vec3s v = vec_make(0, -lengths[s], -0.5f * lengths[s]);
    vec3s want = vec_normalize(v), got = glms_vec3_normalize(v);
    CHECK_THAT(&c, memcmp(&want, &got, sizeof want) == 0,
               "(0, -1, -0.5) times %g: expected vec_normalize's (%.9g, %.9g, %.9g), "
               "got (%.9g, %.9g, %.9g)", (double)lengths[s], (double)want.x,
               (double)want.y, (double)want.z, (double)got.x, (double)got.y, (double)got.z);
  }
}

/* A fixed stream of numbers in [-1, 1) (a 32-bit LCG): the cases below. */
static float next_unit(uint32_t *s)
{
  *s = *s * 1664525u + 1013904223u;
  return (float)((int32_t)(*s >> 8) - (1 << 23)) * 0x1p-23f;
}

/* The camera's m (v, w) (step 03's camera_ray): within the rounding of four
 * products and three sums, 4 x 2^-24 of the sum of the terms' magnitudes,
 * against long double; and cglm's name is the project's function, whose one
 * order of operations gives the same bits on every CPU. */
Test(vec, mat4_mulv3_is_the_product_in_one_order)
{
  Check c = CHECK("vec_mat4_mulv3", DOC);
  uint32_t s = 7;
  for (int n = 0; n < 1000; n++) {
    mat4s m;
    for (int i = 0; i < 4; i++)
      for (int k = 0; k < 4; k++)
        m.raw[i][k] = next_unit(&s) * (k == 3 ? 0.0f : 100.0f);
    float x = next_unit(&s), y = next_unit(&s), z = next_unit(&s);
    vec3s v = vec_make(x, y, z);
    float w = n % 2 ? 1.0f : 0.0f;
    vec3s got = vec_mat4_mulv3(m, v, w), cglm_name = glms_mat4_mulv3(m, v, w);
    for (int k = 0; k < 3; k++) {
      long double terms[4] = {(long double)m.raw[0][k] * v.x, (long double)m.raw[1][k] * v.y,
                              (long double)m.raw[2][k] * v.z, (long double)m.raw[3][k] * w};
      long double exact = terms[0] + terms[1] + terms[2] + terms[3];
      long double mag = fabsl(terms[0]) + fabsl(terms[1]) + fabsl(terms[2]) + fabsl(terms[3]);
      CHECK_NEAR(&c, (double)exact, got.raw[k], (double)(4.0L * mag * 0x1p-24L),
                 "case %d, w = %g: component %d of m (v, w)", n, (double)w, k);
      CHECK_THAT(&c, memcmp(&got.raw[k], &cglm_name.raw[k], sizeof(float)) == 0,
                 "case %d: glms_mat4_mulv3 must be vec_mat4_mulv3 (common/vec.h), component %d: "
                 "%.9g against %.9g", n, k, (double)cglm_name.raw[k], (double)got.raw[k]);
    }
  }
  CHECK_DONE(&c);
}
