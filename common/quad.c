/* Ray-parallelogram intersection, the shape of area lights (step 08).
 * docs/08-area-lights.md. */
#include "quad.h"

#include "box.h"
#include "surface.h"

Quad quad_make(vec3s corner, vec3s edge1, vec3s edge2)
{
  vec3s cross = glms_vec3_cross(edge1, edge2);
  Quad q = {.corner = corner, .edge1 = edge1, .edge2 = edge2};
  q.area = glms_vec3_norm(cross);
  q.normal = q.area > 0.0f ? glms_vec3_scale(cross, 1.0f / q.area) : glms_vec3_zero();
  return q;
}

float quad_hit_t(const Quad *q, Ray r, float tmax)
{
  float d_n = glms_vec3_dot(r.d, q->normal);
  if (d_n == 0.0f) /* parallel to the light: x / 0 would be rejected below too */
    return INFINITY;
  float t = glms_vec3_dot(glms_vec3_sub(q->corner, r.o), q->normal) / d_n;
  if (!(t > 0.0f && t < tmax))
    return INFINITY;
  /* Parameters of the hit: rel = a e1 + b e2, so rel x e2 = a (e1 x e2) and
   * e1 x rel = b (e1 x e2); project both on the unit normal, divide by area. */
  vec3s rel = glms_vec3_sub(ray_at(r, t), q->corner);
  float a = glms_vec3_dot(glms_vec3_cross(rel, q->edge2), q->normal) / q->area;
  float b = glms_vec3_dot(glms_vec3_cross(q->edge1, rel), q->normal) / q->area;
  return (a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f) ? t : INFINITY;
}

void flat_hit_fill(vec3s point, vec3s normal, Ray r, float t, Hit *hit)
{
  vec3s p = ray_at(r, t);
  float off = glms_vec3_dot(glms_vec3_sub(p, point), normal);
  hit->t = t;
  hit->p = glms_vec3_sub(p, glms_vec3_scale(normal, off));
  hit->backface = glms_vec3_dot(r.d, normal) > 0.0f;
  hit->n = hit->backface ? glms_vec3_negate(normal) : normal;
  hit->p_err = RAY_POINT_ERR * (vec_max_abs(hit->p) + vec_max_abs(point));
}

void quad_hit_fill(const Quad *q, Ray r, float t, Hit *hit)
{
  flat_hit_fill(q->corner, q->normal, r, t, hit);
}

vec3s quad_point(const Quad *q, float a, float b)
{
  return glms_vec3_add(q->corner, glms_vec3_add(glms_vec3_scale(q->edge1, a),
                                                glms_vec3_scale(q->edge2, b)));
}

/* The box of the four corners, padded by box_margin. */
Box quad_bounds(const Quad *q)
{
  vec3s c[4] = {q->corner, glms_vec3_add(q->corner, q->edge1), glms_vec3_add(q->corner, q->edge2),
                quad_point(q, 1.0f, 1.0f)};
  Box b = {c[0], c[0]};
  for (int k = 1; k < 4; k++)
    b = box_union(b, (Box){c[k], c[k]});
  float size = vec_max_abs(q->edge1) + vec_max_abs(q->edge2);
  float pad = box_margin(size, fmaxf(vec_max_abs(b.min), vec_max_abs(b.max)));
  return (Box){glms_vec3_subs(b.min, pad), glms_vec3_adds(b.max, pad)};
}

/* For the shape conformance suite: a parallelogram centred at `at` facing
 * `axis`, edges of length `size` and 0.75 size at 80 degrees, and its
 * surface in long double: corner + u edge1 + v edge2, its normal that of
 * edge1 x edge2 computed there; on the quad for (u, v) in [0, 1]^2, false
 * outside. */
Quad quad_example(vec3s at, float size, vec3s axis)
{
  vec3s t1, t2;
  surface_frame(axis, &t1, &t2);
  /* edge2 at 80 degrees from edge1: cos 80 = 0.173648, sin 80 = 0.984808 */
  vec3s e1 = glms_vec3_scale(t1, size);
  vec3s e2 = glms_vec3_scale(glms_vec3_add(glms_vec3_scale(t1, 0.173648f),
                                           glms_vec3_scale(t2, 0.984808f)), 0.75f * size);
  vec3s corner = glms_vec3_sub(at, glms_vec3_scale(glms_vec3_add(e1, e2), 0.5f));
  return quad_make(corner, e1, e2);
}

bool quad_surface(const Quad *q, long double u, long double v, SurfacePoint *sp)
{
  long double c[3], e1[3], e2[3];
  surface_ld(q->corner, c);
  surface_ld(q->edge1, e1);
  surface_ld(q->edge2, e2);
  surface_cross(e1, e2, sp->n);
  surface_normalize(sp->n);
  for (int a = 0; a < 3; a++)
    sp->p[a] = c[a] + u * e1[a] + v * e2[a];
  return u >= 0 && u <= 1 && v >= 0 && v <= 1;
}
