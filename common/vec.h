/* Small vector helpers on top of cglm's struct API (vec3s by value).
 * Used from step 01 on; Debian's cglm 0.8.8 lacks a constructor and reflect.
 * See docs/02-intersection.md for the conventions. */
#ifndef RT_VEC_H
#define RT_VEC_H

#include <cglm/struct.h>
#include <math.h>

/* The vector (x, y, z). */
static inline vec3s vec_make(float x, float y, float z)
{
  vec3s v = {.x = x, .y = y, .z = z};
  return v;
}

/* Mirror `in` about the unit normal `n`: in - 2 (in.n) n (GLSL's reflect). */
static inline vec3s vec_reflect(vec3s in, vec3s n)
{
  return glms_vec3_sub(in, glms_vec3_scale(n, 2.0f * glms_vec3_dot(in, n)));
}

/* v with component `axis` (0, 1, 2: x, y, z) replaced by `value`. Written
 * as three selects: assigning v.raw[axis] would send v through memory, and
 * reading it back whole then waits on the store (about 5 % of step 05's
 * frame, docs/performance.md). */
static inline vec3s vec_with(vec3s v, int axis, float value)
{
  return vec_make(axis == 0 ? value : v.x, axis == 1 ? value : v.y, axis == 2 ? value : v.z);
}

/* fmaxf(a, b) (a NaN loses to a number) without the call to libm that gcc
 * makes for fmaxf: two compares and a select. */
static inline float vec_fmax(float a, float b)
{
  return a > b || b != b ? a : b;
}

/* Largest absolute component, |v|_inf. */
static inline float vec_max_abs(vec3s v)
{
  return vec_fmax(fabsf(v.x), vec_fmax(fabsf(v.y), fabsf(v.z)));
}

/* Sum of absolute components, |v|_1. */
static inline float vec_sum_abs(vec3s v)
{
  return fabsf(v.x) + fabsf(v.y) + fabsf(v.z);
}

/* True when every component is finite (no NaN, no infinity). */
static inline int vec_is_finite(vec3s v)
{
  return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* True when every component is exactly zero. */
static inline int vec_is_zero(vec3s v)
{
  return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f;
}

/* v / |v|, the unit vector along v; (0, 0, 0) for v = 0; NaN components for
 * an infinite or NaN v. cglm's normalize cannot be relied on here: since
 * cglm 0.9 it returns (0, 0, 0) for any v shorter than FLT_EPSILON (1.2e-7),
 * and the scene format accepts directions of length 1e-18. Computed as
 * v * (1 / sqrt(v.v)), cglm 0.8.8's formula bit for bit, when v.v is in
 * [2^-100, 2^100]; any other v is first multiplied by the power of two
 * (exact) that brings its largest component into [0.5, 1), so a tiny or huge
 * vector comes out as accurate as one of length 1. docs/accuracy.md. */
static inline vec3s vec_normalize(vec3s v)
{
  float n2 = glms_vec3_dot(v, v);
  if (!(n2 >= 0x1p-100f && n2 <= 0x1p100f)) {
    float m = vec_max_abs(v);
    if (m == 0.0f)
      return glms_vec3_zero();
    if (isfinite(m)) {
      int e;
      frexpf(m, &e);
      v = vec_make(ldexpf(v.x, -e), ldexpf(v.y, -e), ldexpf(v.z, -e));
      n2 = glms_vec3_dot(v, v);
    }
  }
  return glms_vec3_scale(v, 1.0f / sqrtf(n2));
}

/* m (v, w): the 4x4 matrix m times the point (w = 1) or direction (w = 0) v,
 * its first three rows. Each component is summed in one order,
 * ((m3 w + m2 z) + m1 y) + m0 x, every product and sum rounded: cglm's
 * mat4_mulv is SIMD, with a fused multiply-add where the compiler targets FMA
 * (-march=native on most x86-64 CPUs) and another order on arm64 (NEON), so
 * the same camera gave rays differing in their last bits from machine to
 * machine. The order is that of cglm's SSE2 code without FMA (the portable
 * x86-64 build): its pictures are unchanged. docs/accuracy.md. */
static inline vec3s vec_mat4_mulv3(mat4s m, vec3s v, float w)
{
  vec3s r;
  for (int k = 0; k < 3; k++)
    r.raw[k] = ((m.raw[3][k] * w + m.raw[2][k] * v.z) + m.raw[1][k] * v.y) + m.raw[0][k] * v.x;
  return r;
}

/* Every glms_vec3_normalize and glms_mat4_mulv3 of the project (the steps'
 * solution regions included) is vec_normalize and vec_mat4_mulv3: the same
 * results whatever cglm's version, the compiler's flags or the CPU. cglm's
 * own definitions are above (<cglm/struct.h>), untouched. */
#define glms_vec3_normalize(v) vec_normalize(v)
#define glms_mat4_mulv3(m, v, w) vec_mat4_mulv3(m, v, w)

#endif
