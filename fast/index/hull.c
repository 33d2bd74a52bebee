/* Shadow volume of an area light (docs/08-area-lights.md, "Points nothing can
 * shadow"): conservative tests that a shape cannot stop any shadow ray from a
 * hit point to a parallelogram light, as the float intersection code computes
 * those rays. Every test errs toward "may meet". */
#include "index/hull.h"

#include <math.h>

/* Largest coordinate magnitude of the exact corners and of their error: a
 * sample quad_point(a, b), a, b in [0, 1], is the exact point c + a e1 + b e2
 * to within three roundings of numbers below |c| + |e1| + |e2| per axis. */
static void hull_quad(ShadowHull *h, const Quad *q)
{
  for (int a = 0; a < 3; a++) {
    double c = q->corner.raw[a], e1 = q->edge1.raw[a], e2 = q->edge2.raw[a];
    double err = 0x1p-20 * (fabs(c) + fabs(e1) + fabs(e2));
    h->quad_lo[a] = c + fmin(0.0, e1) + fmin(0.0, e2) - err;
    h->quad_hi[a] = c + fmax(0.0, e1) + fmax(0.0, e2) + err;
    h->corner[0][a] = c;
    h->corner[1][a] = c + e1;
    h->corner[2][a] = c + e1 + e2;
    h->corner[3][a] = c + e2;
  }
}

static vec3s corner_f(const ShadowHull *h, int j)
{
  return vec_make((float)h->corner[j][0], (float)h->corner[j][1], (float)h->corner[j][2]);
}

/* Extent of the hull from p along unit u: its largest u . (v - p) over the
 * vertices p, o and the corners (a linear function peaks at a vertex). */
static float hull_reach(const ShadowHull *h, vec3s u)
{
  float best = glms_vec3_dot(u, glms_vec3_sub(h->o, h->p));
  best = best > 0.0f ? best : 0.0f;
  for (int j = 0; j < 4; j++) {
    float s = glms_vec3_dot(u, glms_vec3_sub(corner_f(h, j), h->p));
    best = s > best ? s : best;
  }
  return best;
}

/* Add unit u / |u|, turned to point away from `inside` - p. */
static void add_dir(ShadowHull *h, vec3s u, vec3s inside)
{
  float len = glms_vec3_norm(u);
  if (!(len > 0x1p-40f)) /* degenerate side (p in the light's plane): skipped */
    return;
  u = glms_vec3_scale(u, glms_vec3_dot(u, glms_vec3_sub(inside, h->p)) > 0.0f ? -1.0f / len
                                                                           : 1.0f / len);
  h->dir[h->n_dirs] = u;
  h->reach[h->n_dirs++] = hull_reach(h, u);
}

ShadowHull hull_make(vec3s o, const Quad *q)
{
  ShadowHull h = {.p = o, .o = o};
  hull_quad(&h, q);
  float scale = fmaxf(vec_max_abs(h.p), vec_max_abs(h.o)), far = 0.0f;
  h.lo = h.hi = h.p;
  h.lo = glms_vec3_minv(h.lo, h.o);
  h.hi = glms_vec3_maxv(h.hi, h.o);
  for (int j = 0; j < 4; j++) {
    vec3s c = corner_f(&h, j);
    scale = fmaxf(scale, vec_max_abs(c));
    far = fmaxf(far, vec_max_abs(glms_vec3_sub(c, h.p)));
    h.lo = glms_vec3_minv(h.lo, c);
    h.hi = glms_vec3_maxv(h.hi, c);
  }
  /* Rounding moves a shadow ray off the exact hull by a few ulps of these
   * lengths (sample point, direction from the shaded point rather than from
   * the origin pushed off it, the ray's end short of the light:
   * accel.c's toward_area); 2^-14 of them is far above that and still
   * invisible geometrically. */
  h.margin = 0x1p-14f * (scale + far);
  /* The ray's end may stray from the quad by what accel.c's toward_area
   * admits (2^-19 of the quad's size and of the ray's length, at most 3 far
   * per axis): lean covers it along f, with as much again for rounding. */
  h.lean = 0x1p-15 * ((double)far + q->area + vec_max_abs(q->corner) +
                      vec_max_abs(q->edge1) + vec_max_abs(q->edge2) + scale);
  /* The four sides through p and an edge, outward (away from the light's
   * centre), then the light's plane and the plane through p parallel to it. */
  vec3s mid = glms_vec3_scale(glms_vec3_add(corner_f(&h, 0), corner_f(&h, 2)), 0.5f);
  for (int j = 0; j < 4; j++)
    add_dir(&h, glms_vec3_cross(glms_vec3_sub(corner_f(&h, j), h.p),
                                glms_vec3_sub(corner_f(&h, (j + 1) % 4), h.p)), mid);
  add_dir(&h, q->normal, h.p);
  add_dir(&h, glms_vec3_negate(q->normal), glms_vec3_add(h.p, q->normal));
  return h;
}

/* Every ray from o toward the light leaves the sphere: o is outside (c >= 0
 * as the intersection code rounds it, the same expression) and f . d > 0 for
 * each direction d (then b < 0, both roots are <= 0: no hit). f . (x - p) is
 * linear in the light's point x, so the corners decide, with a margin for
 * the rounding of the sample points, of d and of the double sum b. */
static bool rays_leave_sphere(const ShadowHull *h, vec3s center, float r)
{
  double fx = (double)h->o.x - center.x, fy = (double)h->o.y - center.y,
         fz = (double)h->o.z - center.z;
  float c = (float)((fx * fx + fy * fy + fz * fz) - (double)r * r);
  if (!(c >= 0.0f))
    return false;
  double need = (fabs(fx) + fabs(fy) + fabs(fz)) * h->lean;
  for (int j = 0; j < 4; j++) {
    double s = fx * (h->corner[j][0] - h->p.x) + fy * (h->corner[j][1] - h->p.y) +
               fz * (h->corner[j][2] - h->p.z);
    if (!(s > need))
      return false;
  }
  return true;
}

bool hull_may_meet_sphere(const ShadowHull *h, vec3s c, float r)
{
  float m = h->margin + 0x1p-14f * (vec_max_abs(c) + r) + r;
  for (int a = 0; a < 3; a++)
    if (c.raw[a] - m > h->hi.raw[a] || c.raw[a] + m < h->lo.raw[a])
      return false;
  vec3s pc = glms_vec3_sub(c, h->p);
  for (int k = 0; k < h->n_dirs; k++)
    if (glms_vec3_dot(h->dir[k], pc) - m > h->reach[k])
      return false;
  return !rays_leave_sphere(h, c, r);
}

bool hull_may_meet_box(const ShadowHull *h, const float lo[3], const float hi[3])
{
  float big = 0.0f;
  for (int a = 0; a < 3; a++)
    big = fmaxf(big, fmaxf(fabsf(lo[a]), fabsf(hi[a])));
  float m = h->margin + 0x1p-14f * big;
  for (int a = 0; a < 3; a++)
    if (lo[a] - m > h->hi.raw[a] || hi[a] + m < h->lo.raw[a])
      return false;
  for (int k = 0; k < h->n_dirs; k++) {
    vec3s u = h->dir[k], near; /* the box's corner lowest along u */
    for (int a = 0; a < 3; a++)
      near.raw[a] = u.raw[a] > 0.0f ? lo[a] : hi[a];
    if (glms_vec3_dot(u, glms_vec3_sub(near, h->p)) - m > h->reach[k])
      return false;
  }
  return true;
}

/* Axis-aligned plane x[a] = Q: plane_hit_t's t is (Q - o[a]) / d[a] up to
 * exact zeros and the normal's sign, so it is positive only when d[a] points
 * from o toward the plane, and sign(d[a]) = sign(x[a] - p[a]) for the sample
 * x and the shaded point p (a positive scaling), which lies within a rounding
 * of o: the margin covers it. */
static bool axis_plane_may_meet(const ShadowHull *h, const Plane *pl)
{
  int a = pl->axis;
  float q = pl->point.raw[a], o = h->o.raw[a];
  if (o > q)
    return !(h->quad_lo[a] > (double)o + h->margin);
  if (o < q)
    return !(h->quad_hi[a] < (double)o - h->margin);
  return false; /* o on the plane: t = 0 / d[a], never positive */
}

bool hull_may_meet_plane(const ShadowHull *h, const Plane *pl)
{
  if (pl->axis >= 0 && !axis_plane_may_meet(h, pl))
    return false;
  /* Any plane: the hull entirely on one side, by the margin. */
  double side[5], m = h->margin + 0x1p-14 * vec_max_abs(pl->point);
  side[4] = glms_vec3_dot(pl->normal, glms_vec3_sub(h->o, pl->point));
  for (int j = 0; j < 4; j++)
    side[j] = pl->normal.x * (h->corner[j][0] - pl->point.x) +
              pl->normal.y * (h->corner[j][1] - pl->point.y) +
              pl->normal.z * (h->corner[j][2] - pl->point.z);
  bool above = true, below = true;
  for (int j = 0; j < 5; j++) {
    above = above && side[j] > m;
    below = below && side[j] < -m;
  }
  return !(above || below);
}
