/* Ray-plane intersection (step 02). docs/02-intersection.md. */
#include "plane.h"

Plane plane_make(vec3s point, vec3s normal)
{
  Plane pl = {.point = point, .normal = glms_vec3_normalize(normal), .axis = -1};
  /* A normal along a coordinate axis is stored exactly, and hits are then
   * snapped exactly onto the plane. */
  for (int a = 0; a < 3; a++) {
    if (normal.raw[(a + 1) % 3] == 0.0f && normal.raw[(a + 2) % 3] == 0.0f) {
      pl.axis = a;
      pl.normal = glms_vec3_zero();
      pl.normal.raw[a] = normal.raw[a] > 0.0f ? 1.0f : -1.0f;
    }
  }
  return pl;
}

float plane_hit_t(const Plane *pl, Ray r, float tmax)
{
  /* BEGIN SOLUTION step 02 */
  /* (o + t d - q) . n = 0  =>  t = (q - o) . n / (d . n). A ray parallel to the
   * plane divides by zero: t is infinite or NaN, and the test below rejects it. */
  float t = glms_vec3_dot(glms_vec3_sub(pl->point, r.o), pl->normal) /
            glms_vec3_dot(r.d, pl->normal);
  return (t > 0.0f && t < tmax) ? t : INFINITY;
  /* STUB: return INFINITY; */
  /* END SOLUTION */
}

void plane_hit_fill(const Plane *pl, Ray r, float t, Hit *hit)
{
  /* BEGIN SOLUTION step 02 */
  vec3s p = ray_at(r, t);
  if (pl->axis >= 0) {
    p = vec_with(p, pl->axis, pl->point.raw[pl->axis]);
    hit->p_err = 0.0f;
  } else {
    float off = glms_vec3_dot(glms_vec3_sub(p, pl->point), pl->normal);
    p = glms_vec3_sub(p, glms_vec3_scale(pl->normal, off));
    hit->p_err = RAY_POINT_ERR * (vec_max_abs(p) + vec_max_abs(pl->point));
  }
  hit->t = t;
  hit->p = p;
  hit->backface = glms_vec3_dot(r.d, pl->normal) > 0.0f;
  hit->n = hit->backface ? glms_vec3_negate(pl->normal) : pl->normal;
  /* END SOLUTION */
}

Box plane_bounds(const Plane *pl)
{
  Box b = {vec_make(-INFINITY, -INFINITY, -INFINITY), vec_make(INFINITY, INFINITY, INFINITY)};
  if (pl->axis >= 0) {
    float at = pl->point.raw[pl->axis], pad = box_margin(0.0f, fabsf(at));
    b.min = vec_with(b.min, pl->axis, at - pad);
    b.max = vec_with(b.max, pl->axis, at + pad);
  }
  return b;
}

Plane plane_example(vec3s at, float size, vec3s axis)
{
  (void)size;
  return plane_make(at, axis);
}

bool plane_surface(const Plane *pl, long double u, long double v, SurfacePoint *sp)
{
  long double q[3], t1[3], t2[3];
  surface_ld(pl->point, q);
  surface_ld(pl->normal, sp->n);
  surface_normalize(sp->n);
  surface_basis(sp->n, t1, t2);
  for (int a = 0; a < 3; a++)
    sp->p[a] = q[a] + (u - 0.5L) * t1[a] + (v - 0.5L) * t2[a];
  return true;
}
