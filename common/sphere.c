/* Ray-sphere intersection (step 02) in the numerically stable form of Ray
 * Tracing Gems, ch. 7. docs/02-intersection.md, docs/accuracy.md. */
#include "sphere.h"

#include "box.h"
#include "surface.h"

float sphere_hit_t(const Sphere *s, Ray r, float tmax)
{
  /* BEGIN SOLUTION step 02 */
  /* With d unit the quadratic is t^2 - 2 b t + c = 0, b = -f.d, f = o - c. */
  vec3s f = glms_vec3_sub(r.o, s->center);
  /* Quick reject, in float: the line passes farther than r from the centre
   * by a margin (2^-17 |f|^2) far above the rounding of this test and of the
   * exact one below, so it only skips rays the exact test rejects too (same
   * answers, bit for bit; docs/accuracy.md, "Cost"). */
  float fd = glms_vec3_dot(f, r.d), ff = glms_vec3_dot(f, f);
  if (ff - fd * fd > s->radius * s->radius + 0x1p-17f * ff)
    return INFINITY;
  /* The difference of two floats is exact in double, and so are products of
   * floats: b and c are formed there from the exact f and rounded once. */
  double fx = (double)r.o.x - s->center.x, fy = (double)r.o.y - s->center.y,
         fz = (double)r.o.z - s->center.z;
  float b = (float)-(fx * r.d.x + fy * r.d.y + fz * r.d.z);
  float c = (float)((fx * fx + fy * fy + fz * fz) - (double)s->radius * s->radius);
  /* The discriminant as r^2 - (distance from the centre to the line)^2: the
   * textbook b^2 - c cancels catastrophically for far or small spheres. The
   * perpendicular f + b d is projected off d once more (Gram-Schmidt twice):
   * that removes what rounding left along d, which would reach r past
   * |f| = 1e6 r.
   * (f above equals the double f rounded once: float subtraction is
   * correctly rounded.) */
  vec3s to_line = glms_vec3_add(f, glms_vec3_scale(r.d, b));
  to_line = glms_vec3_sub(to_line, glms_vec3_scale(r.d, glms_vec3_dot(to_line, r.d)));
  float disc = s->radius * s->radius - glms_vec3_dot(to_line, to_line);
  if (!(disc >= 0.0f))
    return INFINITY;
  /* The root of larger magnitude without cancellation, the other from the
   * product of the roots, t0 t1 = c. */
  float q = b + copysignf(sqrtf(disc), b);
  float t0 = c / q, t1 = q;
  if (t0 > t1) {
    float tmp = t0;
    t0 = t1;
    t1 = tmp;
  }
  /* Written so that NaN fails: the nearest root in (0, tmax). */
  if (t0 > 0.0f && t0 < tmax)
    return t0;
  if (t1 > 0.0f && t1 < tmax)
    return t1;
  return INFINITY;
  /* STUB: return INFINITY; */
  /* END SOLUTION */
}

void sphere_hit_fill(const Sphere *s, Ray r, float t, Hit *hit)
{
  /* BEGIN SOLUTION step 02 */
  /* The hit relative to the centre, formed as (o - c) + t d: its error is a
   * few ulps of |o - c| and t, however far the sphere is from the origin
   * ((o + t d) - c would carry the rounding of o + t d, ulps of |c|: 10 bits
   * of the normal at |c| = 1000 r; docs/02-intersection.md, "The math"). */
  vec3s rel = glms_vec3_add(glms_vec3_sub(r.o, s->center), glms_vec3_scale(r.d, t));
  float len = glms_vec3_norm(rel);
  /* A sphere smaller than the spacing of floats at its position can round
   * the hit onto its centre: take the point facing the ray. */
  if (!(len > 0.0f)) {
    rel = glms_vec3_negate(r.d);
    len = 1.0f;
  }
  /* Scaled to the radius: p re-projected onto the sphere, its error a few
   * ulps of |c| + r whatever t was (docs/accuracy.md). */
  rel = glms_vec3_scale(rel, s->radius / len);
  vec3s n_out = glms_vec3_scale(rel, 1.0f / s->radius);
  hit->t = t;
  hit->p = glms_vec3_add(s->center, rel);
  hit->backface = glms_vec3_dot(n_out, r.d) > 0.0f;
  hit->n = hit->backface ? glms_vec3_negate(n_out) : n_out;
  hit->p_err = RAY_POINT_ERR * (vec_max_abs(s->center) + s->radius);
  /* END SOLUTION */
}

/* The cube around the sphere, padded by box_margin. */
Box sphere_bounds(const Sphere *s)
{
  float r = s->radius, pad = box_margin(r, vec_max_abs(s->center) + r);
  return box_around(s->center, vec_make(r, r, r), pad);
}

/* For the shape conformance suite: the sphere of radius `size` centred at
 * `at` (`axis` unused), and its surface in long double: the point at polar
 * angle pi v from +z and azimuth 2 pi u, its outward normal; on the sphere
 * for every (u, v). */
Sphere sphere_example(vec3s at, float size, vec3s axis)
{
  (void)axis;
  return (Sphere){.center = at, .radius = size};
}

bool sphere_surface(const Sphere *s, long double u, long double v, SurfacePoint *sp)
{
  const long double pi = 3.141592653589793238462643383279502884L;
  long double th = pi * v, ph = 2 * pi * u, c[3];
  long double n[3] = {sinl(th) * cosl(ph), sinl(th) * sinl(ph), cosl(th)};
  surface_ld(s->center, c);
  for (int a = 0; a < 3; a++) {
    sp->n[a] = n[a];
    sp->p[a] = c[a] + (long double)s->radius * n[a];
  }
  return true;
}
