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

/* Largest absolute component, |v|_inf: a NaN component loses to a number, as
 * in fmaxf, by compares and selects (gcc calls libm for fmaxf). */
static inline float vec_max_abs(vec3s v)
{
  float x = fabsf(v.x), y = fabsf(v.y), z = fabsf(v.z);
  float yz = y > z || z != z ? y : z;
  return x > yz || yz != yz ? x : yz;
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
 * an infinite or NaN v. cglm 0.8.8's formula, v (1 / sqrt(v.v)), on every
 * cglm (0.9 returns 0 for any v shorter than 1.2e-7), a tiny or huge v first
 * scaled by an exact power of two. docs/accuracy.md, "What the code does,
 * and why". */
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
 * its first three rows, each summed in one fixed order with every product
 * rounded, so that camera rays come out alike on every CPU, compiler and
 * cglm (cglm's SIMD order differs). docs/accuracy.md. */
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
