/* Acceleration structure (docs/performance.md): lit spheres in blocks of
 * LANES, tested by one branch-free loop the compiler vectorizes (it computes
 * exactly common/sphere.c's formula, operation for operation, so the answers
 * are bit-identical), found through a BVH (common/bvh.c) when there are many.
 * Everything else (planes, lights' shapes) is tested one by one. This file
 * answers the queries; accel_build.c builds the layout (accel_layout.h). */
#include "accel.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel_layout.h"
#include "hull.h"

enum { STACK = 64 }; /* BVH traversal stack */

/* plane_hit_t for a plane whose normal is +-e_a: its dot products are
 * (q[a] - o[a]) n[a] and d[a] n[a] plus exact zeros, and n[a] = +-1 cancels in
 * the quotient, so t = (q[a] - o[a]) / d[a] is the same float (a zero
 * denominator's sign may differ: t is then infinite or NaN, rejected both
 * ways). Finite coordinates assumed, as everywhere. */
static float axis_plane_hit_t(const Plane *pl, Ray r, float tmax)
{
  int a = pl->axis;
  float num = pl->point.raw[a] - r.o.raw[a], den = r.d.raw[a];
  /* The quotient's sign is the product of the signs: opposite signs (a ray
   * going away from the plane, about half of all rays) or a zero numerator
   * give t <= 0 or NaN, rejected without the division. */
  if (signbit(num) != signbit(den) || num == 0.0f)
    return INFINITY;
  float t = num / den;
  return (t > 0.0f && t < tmax) ? t : INFINITY;
}

float accel_instance_hit_t(const Instance *inst, Ray r, float tmax)
{
  switch (inst->shape) {
  case SHAPE_SPHERE: return sphere_hit_t(&inst->sphere, r, tmax);
  case SHAPE_PLANE:
    return inst->plane.axis >= 0 ? axis_plane_hit_t(&inst->plane, r, tmax)
                                 : plane_hit_t(&inst->plane, r, tmax);
  case SHAPE_QUAD: return quad_hit_t(&inst->quad, r, tmax);
  }
  return INFINITY;
}

/* sphere_hit_t for the LANES spheres of a block (common/sphere.c explains the
 * stable form). Same operations in the same order, no contraction: each lane
 * rounds exactly as the scalar function does. Selects instead of branches,
 * except one: when the ray's line misses every sphere of the block (most rays,
 * most blocks) the square roots and divisions are skipped. False then. */
static bool block_hit_t(const SphereBlock *restrict blk, Ray r, float tmax,
                        float *restrict t)
{
  float dx = r.d.x, dy = r.d.y, dz = r.d.z;
  float b[LANES], disc[LANES];
  int any = 0;
  for (int k = 0; k < LANES; k++) {
    /* f = o - c exactly in double; b rounded once from it. */
    double fx = (double)r.o.x - blk->cx[k], fy = (double)r.o.y - blk->cy[k],
           fz = (double)r.o.z - blk->cz[k];
    b[k] = (float)-(fx * dx + fy * dy + fz * dz);
    /* The perpendicular f + b d, then a second Gram-Schmidt pass along d. */
    float lx = (float)fx + dx * b[k], ly = (float)fy + dy * b[k], lz = (float)fz + dz * b[k];
    float along = lx * dx + ly * dy + lz * dz;
    lx = lx - dx * along;
    ly = ly - dy * along;
    lz = lz - dz * along;
    disc[k] = blk->rad[k] * blk->rad[k] - (lx * lx + ly * ly + lz * lz);
    any |= disc[k] >= 0.0f;
  }
  if (!any)
    return false;
  for (int k = 0; k < LANES; k++) {
    /* c = |f|^2 - r^2 in double (products of floats are exact), rounded once. */
    double fx = (double)r.o.x - blk->cx[k], fy = (double)r.o.y - blk->cy[k],
           fz = (double)r.o.z - blk->cz[k], rad = (double)blk->rad[k];
    float c = (float)((fx * fx + fy * fy + fz * fz) - rad * blk->rad[k]);
    float q = b[k] + copysignf(sqrtf(disc[k] >= 0.0f ? disc[k] : 0.0f), b[k]);
    float t0 = c / q, t1 = q;
    float lo = t0 > t1 ? t1 : t0, hi = t0 > t1 ? t0 : t1;
    float hit = (hi > 0.0f && hi < tmax) ? hi : INFINITY;
    hit = (lo > 0.0f && lo < tmax) ? lo : hit;
    t[k] = disc[k] >= 0.0f ? hit : INFINITY;
  }
  return true;
}

/* False only when the ray's line passes clear of the block's bounding sphere,
 * so that no lane of block_hit_t can find disc >= 0: a cheap test before the
 * kernel in the flat layout (a BVH leaf has its box instead). It rejects when
 * |l|^2 > R^2 (1 + 2^-8) + 2^-27 |f|^2, which implies |l| > R + 2^-18 |f|:
 * that margin is 16 times the rounding error of either computation of |l|
 * (a few ulps of |f|), so a rejected ray is clear of every sphere. */
static bool block_near(const SphereBlock *blk, Ray r)
{
  vec3s f = glms_vec3_sub(r.o, blk->bound_c);
  vec3s l = glms_vec3_sub(f, glms_vec3_scale(r.d, glms_vec3_dot(f, r.d)));
  float limit = blk->bound_r2 * (1.0f + 0x1p-8f) + 0x1p-27f * glms_vec3_dot(f, f);
  return !(glms_vec3_dot(l, l) > limit);
}

/* The closest hit so far: distance, instance index (INT_MAX: none). */
typedef struct Best {
  float t;
  int inst;
} Best;

/* Lanes hold their instances in increasing order (accel_build sorts them), so
 * the first lane at the block's smallest distance is the plain loop's pick. */
static void block_closest(const SphereBlock *blk, Ray r, float tmax, Best *best)
{
  float t[LANES];
  if (!block_hit_t(blk, r, tmax, t))
    return;
  float t_min = t[0];
  for (int k = 1; k < LANES; k++)
    t_min = t[k] < t_min ? t[k] : t_min;
  if (!(t_min <= best->t && t_min < tmax))
    return;
  int lane = 0;
  while (t[lane] != t_min)
    lane++;
  if (t_min < best->t || blk->inst[lane] < best->inst) {
    best->t = t_min;
    best->inst = blk->inst[lane];
  }
}

static bool block_any(const SphereBlock *blk, Ray r, float tmax)
{
  float t[LANES];
  if (!block_hit_t(blk, r, tmax, t))
    return false;
  bool any = false;
  for (int k = 0; k < LANES; k++)
    any |= t[k] < tmax;
  return any;
}

/* Ray's distance into a node's box; NaN (every comparison false) when it
 * misses it or enters beyond tmax. The exit distance is widened by 3 ulps' worth (PBRT's
 * conservative slab test) so rounding never culls a box the ray touches. */
static float box_enter(const BvhNode *nd, vec3s o, vec3s inv_d, float tmax)
{
  float t_in = 0.0f, t_out = tmax;
  for (int a = 0; a < 3; a++) {
    float t0 = (nd->lo[a] - o.raw[a]) * inv_d.raw[a];
    float t1 = (nd->hi[a] - o.raw[a]) * inv_d.raw[a];
    float near = t0 < t1 ? t0 : t1, far = t0 < t1 ? t1 : t0;
    far *= 1.0f + 6.0f * 0x1p-24f;
    t_in = near > t_in ? near : t_in;
    t_out = far < t_out ? far : t_out;
  }
  return t_in <= t_out ? t_in : NAN;
}

static vec3s inverse_dir(vec3s d)
{
  return vec_make(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
}

/* Closest sphere through the hierarchy: nearer child first, boxes entered
 * beyond the best distance skipped (<=: an equal distance may still win on
 * instance index). */
static void bvh_closest(const struct SceneAccel *acc, Ray r, float tmax, Best *best)
{
  vec3s inv_d = inverse_dir(r.d);
  int stack[STACK], top = 0, node = 0;
  for (;;) {
    const BvhNode *nd = &acc->nodes[node];
    if (box_enter(nd, r.o, inv_d, best->t) <= best->t) {
      if (nd->meta > 0) {
        block_closest(&acc->blocks[nd->index], r, tmax, best);
      } else {
        bool neg = r.d.raw[-1 - nd->meta] < 0.0f;
        stack[top++] = nd->index + !neg;
        node = nd->index + neg;
        continue;
      }
    }
    if (top == 0)
      return;
    node = stack[--top];
  }
}

static bool bvh_any(const struct SceneAccel *acc, Ray r, float tmax)
{
  vec3s inv_d = inverse_dir(r.d);
  int stack[STACK], top = 0, node = 0;
  for (;;) {
    const BvhNode *nd = &acc->nodes[node];
    if (box_enter(nd, r.o, inv_d, tmax) < tmax) {
      if (nd->meta > 0) {
        if (block_any(&acc->blocks[nd->index], r, tmax))
          return true;
      } else {
        stack[top++] = nd->index + 1;
        node = nd->index;
        continue;
      }
    }
    if (top == 0)
      return false;
    node = stack[--top];
  }
}

const Instance *accel_closest(const Scene *scene, Ray r, float *tmax)
{
  const struct SceneAccel *acc = scene->accel;
  Best best = {*tmax, INT_MAX};
  if (acc->nodes) {
    bvh_closest(acc, r, *tmax, &best);
  } else {
    for (int k = 0; k < acc->n_blocks; k++)
      if (block_near(&acc->blocks[k], r))
        block_closest(&acc->blocks[k], r, *tmax, &best);
  }
  for (int k = 0; k < acc->n_others; k++) {
    int idx = acc->others[k];
    float t = accel_instance_hit_t(&scene->instances[idx], r, *tmax);
    if (t < best.t || (t == best.t && t < *tmax && idx < best.inst)) {
      best.t = t;
      best.inst = idx;
    }
  }
  if (best.inst == INT_MAX)
    return NULL;
  *tmax = best.t;
  return &scene->instances[best.inst];
}

bool accel_any(const Scene *scene, Ray r, float tmax)
{
  const struct SceneAccel *acc = scene->accel;
  for (int k = 0; k < acc->n_others_lit; k++)
    if (accel_instance_hit_t(&scene->instances[acc->others[k]], r, tmax) < tmax)
      return true;
  if (acc->nodes)
    return bvh_any(acc, r, tmax);
  for (int k = 0; k < acc->n_blocks; k++)
    if (block_near(&acc->blocks[k], r) && block_any(&acc->blocks[k], r, tmax))
      return true;
  return false;
}

/* Shadow volume query (common/hull.c): same traversal as bvh_any, boxes and
 * spheres tested against the hull instead of a ray. */
static bool block_may_occlude(const SphereBlock *blk, const ShadowHull *h)
{
  for (int k = 0; k < LANES && blk->inst[k] != INT_MAX; k++)
    if (hull_may_meet_sphere(h, vec_make(blk->cx[k], blk->cy[k], blk->cz[k]), blk->rad[k]))
      return true;
  return false;
}

static bool bvh_may_occlude(const struct SceneAccel *acc, const ShadowHull *h)
{
  int stack[STACK], top = 0, node = 0;
  for (;;) {
    const BvhNode *nd = &acc->nodes[node];
    if (hull_may_meet_box(h, nd->lo, nd->hi)) {
      if (nd->meta > 0) {
        if (block_may_occlude(&acc->blocks[nd->index], h))
          return true;
      } else {
        stack[top++] = nd->index + 1;
        node = nd->index;
        continue;
      }
    }
    if (top == 0)
      return false;
    node = stack[--top];
  }
}

bool accel_may_occlude(const Scene *scene, const ShadowHull *h)
{
  const struct SceneAccel *acc = scene->accel;
  for (int k = 0; k < acc->n_others_lit; k++) {
    const Instance *inst = &scene->instances[acc->others[k]];
    if (inst->shape != SHAPE_PLANE || hull_may_meet_plane(h, &inst->plane))
      return true;
  }
  if (acc->nodes)
    return bvh_may_occlude(acc, h);
  for (int k = 0; k < acc->n_blocks; k++) {
    const SphereBlock *blk = &acc->blocks[k];
    float rad = sqrtf(blk->bound_r2) * (1.0f + 0x1p-20f), lo[3], hi[3];
    for (int a = 0; a < 3; a++) { /* the box of the block's bounding sphere */
      lo[a] = blk->bound_c.raw[a] - rad;
      hi[a] = blk->bound_c.raw[a] + rad;
    }
    if (hull_may_meet_box(h, lo, hi) && block_may_occlude(blk, h))
      return true;
  }
  return false;
}
