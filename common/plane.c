/* Ray-plane intersection (step 02). docs/02-intersection.md. */
#include "plane.h"

#include "box.h"
#include "surface.h"

/* v with component `axis` (0, 1, 2: x, y, z) replaced by `value`, as three
 * selects: assigning v.raw[axis] would send v through memory, and reading it
 * back whole then waits on the store (docs/performance.md). */
static inline vec3s vec_with(vec3s v, int axis, float value)
{
  return vec_make(axis == 0 ? value : v.x, axis == 1 ? value : v.y, axis == 2 ? value : v.z);
}

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

/* The plane is unbounded: its box is infinite (-INFINITY to INFINITY) along
 * every axis, except a plane normal to a coordinate axis (axis >= 0), whose
 * box is flat along that axis at the plane's coordinate, padded by
 * box_margin. box_is_bounded tells the two apart from a bounded box. */
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

/* For the shape conformance suite: the plane through `at` with normal `axis`
 * (`size` unused), and its surface in long double: point + (u - 1/2) t1 +
 * (v - 1/2) t2, (t1, t2, normal) orthonormal; on the plane for every (u, v). */
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
