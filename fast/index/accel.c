/* Acceleration structure (docs/performance.md): the lit spheres under a
 * bounding volume hierarchy (fast/index/bvh.c), everything else in a list;
 * in scenes of at most 16 spheres, their cones seen from the eye and the
 * lights (fast/index/cones.c) for the rays those know. The boxes and cones
 * only choose which instances a ray meets; each one met is tested with
 * scene_instance_hit_t, the shape's own function (the hierarchy's spheres
 * with sphere_hit_t, what it calls for them), so the answers are those of
 * scene.c's plain loop. */
#include "index/accel.h"

#include <limits.h>
#include <math.h>
#include "threads.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "index/bvh.h"
#include "index/cones.h"
#include "index/hull.h"

enum {
  STACK = 64,  /* traversal stack: the tree is at most about 60 levels deep */
  LEAF_MAX = 4 /* spheres per leaf of the hierarchy */
};

/* An area light as the any-hit query recognises the shadow rays toward it:
 * its plane and the dual basis of its edges (w . u1, w . u2 are the
 * parallelogram coordinates of corner + w), and how far a ray's end may
 * stray from it. */
typedef struct Area {
  const Quad *quad;
  vec3s corner, normal, u1, u2;
  float stray;      /* 2^-19 of the quad's size: the rounding of its points */
  float per_edges;  /* 1 / (|edge1| + |edge2|) */
} Area;

enum { VIEW_MAX = 8, AREAS_MAX = 8 };

typedef struct Accel {
  SceneIndex base;  /* first member: scene->index points here */
  unsigned id;      /* this build's number, for the shadow memo */
  BvhNode *nodes;   /* nodes[0] is the root; a leaf holds spheres[index ..
                     * index + meta), in increasing instance order */
  int *spheres;     /* instance indices of the hierarchy's shapes, in leaf order */
  Box *boxes;       /* their boxes (scene_instance_bounds), in leaf order, for
                     * the shadow culling; NULL when they are all spheres */
  int *others;      /* instance indices of everything else, lit ones first */
  int n_others, n_others_lit;
  Cones *cones;     /* small scenes: the spheres' cones seen from the eye and
                     * the lights (index/cones.c), or NULL */
  Area areas[AREAS_MAX]; /* the first area lights, when the scene takes
                          * more than SHADOW_VIEW_MIN_SAMPLES samples of each */
  int n_areas;
} Accel;

/* The closest hit so far: distance and instance index (INT_MAX: none). */
typedef struct Best {
  float t;
  int inst;
} Best;

/* The float just above x, for a finite x > 0 (a hit distance): its bits + 1
 * (nextafterf is a library call). */
static float next_up(float x)
{
  uint32_t bits;
  memcpy(&bits, &x, sizeof bits);
  bits++;
  memcpy(&x, &bits, sizeof x);
  return x;
}

/* The limit of the next test: once something is found, just above its
 * distance, so that an equal distance comes back and is compared by index. */
static float limit_of(const Best *best)
{
  return best->inst == INT_MAX ? best->t : next_up(best->t);
}

/* Keep instance `id`, met at t, when it is nearer, or as near and earlier in
 * instance order (the plain loop keeps the first of equal distances). */
static void keep(Best *best, int id, float t)
{
  if (t < best->t || (t == best->t && best->inst != INT_MAX && id < best->inst)) {
    best->t = t;
    best->inst = id;
  }
}

/* Test instance `id` with its shape's function and keep it when nearer. */
static void consider(const Scene *scene, int id, const Ray *r, Best *best)
{
  keep(best, id, scene_instance_hit_t(&scene->instances[id], *r, limit_of(best)));
}

/* The same for a shape of the hierarchy: a sphere (most of them) with
 * sphere_hit_t, which scene_instance_hit_t would call, without the shape's
 * switch, so that the compiler puts the test inside the traversal loop; any
 * other shape through scene_instance_hit_t. */
static float leaf_t(const Scene *scene, int id, const Ray *r, float tmax)
{
  const Instance *inst = &scene->instances[id];
  return inst->shape == SHAPE_SPHERE ? sphere_hit_t(&inst->sphere, *r, tmax)
                                     : scene_instance_hit_t(inst, *r, tmax);
}

/* Ray's distance into a node's box; NaN (every comparison false) when it
 * misses it or enters beyond tmax. The exit distance is widened by 3 ulps'
 * worth (PBRT's conservative slab test) so rounding never culls a box the ray
 * touches. */
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

/* 1 / d per axis; a zero component gives the infinity of its sign (what IEEE
 * division gives, written out so that no division by zero is performed). */
static float inverse(float x)
{
  return x != 0.0f ? 1.0f / x : copysignf(INFINITY, x);
}

static vec3s inverse_dir(vec3s d)
{
  return vec_make(inverse(d.x), inverse(d.y), inverse(d.z));
}

/* Nearer child first; a box entered beyond the best distance is skipped (<=:
 * an equal distance may still win on instance index). */
static void bvh_closest(const Scene *scene, const Accel *acc, const Ray *r, Best *best)
{
  vec3s o = r->o, inv_d = inverse_dir(r->d);
  int stack[STACK], top = 0, node = 0;
  for (;;) {
    const BvhNode *nd = &acc->nodes[node];
    if (box_enter(nd, o, inv_d, best->t) <= best->t) {
      if (nd->meta > 0) {
        for (int k = nd->index; k < nd->index + nd->meta; k++)
          keep(best, acc->spheres[k], leaf_t(scene, acc->spheres[k], r, limit_of(best)));
      } else {
        bool neg = r->d.raw[-1 - nd->meta] < 0.0f;
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

static bool bvh_any(const Scene *scene, const Accel *acc, const Ray *r, float tmax)
{
  vec3s o = r->o, inv_d = inverse_dir(r->d);
  int stack[STACK], top = 0, node = 0;
  for (;;) {
    const BvhNode *nd = &acc->nodes[node];
    if (box_enter(nd, o, inv_d, tmax) < tmax) {
      if (nd->meta > 0) {
        for (int k = nd->index; k < nd->index + nd->meta; k++)
          if (leaf_t(scene, acc->spheres[k], r, tmax) < tmax)
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

/* True when r cannot meet instance inst at any t > 0 because inst is an
 * axis-aligned plane that r starts on, or leaves from the side r moves
 * toward: the plane's own test would reject it (the difference of two floats
 * has the sign of the exact one, so the decision is exact), and skipping it
 * saves a division. Rays toward a light above the floor, and camera rays
 * into the sky, are such rays. */
static bool leaves_plane(const Instance *inst, const Ray *r)
{
  if (inst->shape != SHAPE_PLANE || inst->plane.axis < 0)
    return false;
  int a = inst->plane.axis;
  float h = r->o.raw[a] - inst->plane.point.raw[a], d = r->d.raw[a];
  return d != 0.0f && (h == 0.0f || (h > 0.0f && d > 0.0f) || (h < 0.0f && d < 0.0f));
}

/* The planes first: the floor a ray meets bounds the boxes worth entering.
 * The ray stays in the caller's memory, each test's copy taken from there:
 * passed by value, it would be rebuilt on the stack piecewise before every
 * test and read back whole, a stalled load per test (docs/performance.md). */
static const Instance *accel_closest(const Scene *scene, const Ray *r, float *tmax)
{
  const Accel *acc = (const Accel *)scene->index;
  Best best = {*tmax, INT_MAX};
  for (int k = 0; k < acc->n_others; k++)
    if (!leaves_plane(&scene->instances[acc->others[k]], r))
      consider(scene, acc->others[k], r, &best);
  uint32_t mask;
  if (acc->cones && cones_from_eye(acc->cones, r, &mask)) {
    for (const int *ids = cones_spheres(acc->cones); mask; mask &= mask - 1)
      consider(scene, ids[__builtin_ctz(mask)], r, &best);
  } else if (acc->nodes) {
    bvh_closest(scene, acc, r, &best);
  }
  if (best.inst == INT_MAX)
    return NULL;
  *tmax = best.t;
  return &scene->instances[best.inst];
}

/* The lit shapes that may stop a shadow ray from one origin toward one
 * area light (area_shapes): their count n (-1: more than VIEW_MAX, ask the
 * whole index) and instance indices. One per thread, for the last origin
 * and light asked: the light samples of a shading point share their origin,
 * so the hull is built once per point and light. It is a memo: any ray its
 * key admits gets the same answer from ids as from the whole scene. */
typedef struct ShadowMemo {
  unsigned accel;  /* Accel.id of the index it was made for (0: none) */
  int area;        /* index into Accel.areas */
  vec3s o;         /* the rays' origin, compared bit for bit */
  vec3s from;      /* o - corner along the area's normal, u1 and u2 (area_from) */
  int n;
  int ids[VIEW_MAX];
} ShadowMemo;

static _Thread_local ShadowMemo memo;

static int area_shapes(const Scene *scene, const Accel *acc, vec3s o, const Quad *q, int *ids,
                       int max);

/* Origin o as toward_area reads it: o - corner along a's normal, u1, u2. */
static vec3s area_from(const Area *a, vec3s o)
{
  vec3s w = glms_vec3_sub(o, a->corner);
  return vec_make(glms_vec3_dot(w, a->normal), glms_vec3_dot(w, a->u1), glms_vec3_dot(w, a->u2));
}

/* Whether the ray's end o + tmax d lies on area light a (`from`: area_from
 * of o), within what the sample points' rounding, the push of the origin off
 * the surface and ray_shadow_tmax (2^-20 of the length) leave: 2^-19 of the
 * quad's size and of the ray's length. Such a ray lies in the hull of o and
 * the light grown by that much, which hull.c's margins cover (the rounding
 * of these few sums is far below it). */
__attribute__((always_inline)) static inline bool toward_area(const Area *a, vec3s from,
                                                             const Ray *r, float tmax)
{
  vec3s td = glms_vec3_scale(r->d, tmax);
  float stray = a->stray + 0x1p-19f * tmax * vec_sum_abs(r->d), across = stray * a->per_edges;
  float h = from.x + glms_vec3_dot(td, a->normal), u = from.y + glms_vec3_dot(td, a->u1),
        v = from.z + glms_vec3_dot(td, a->u2);
  return fabsf(h) <= stray && u >= -across && u <= 1.0f + across && v >= -across &&
         v <= 1.0f + across;
}

/* The memo for a shadow ray toward an area light, filled for its origin
 * when it is not already; NULL when the ray ends on no area light (a ray
 * toward a directional light has no end). */
static const ShadowMemo *shadow_memo(const Scene *scene, const Accel *acc, const Ray *r,
                                     float tmax)
{
  ShadowMemo *m = &memo;
  if (m->accel == acc->id && memcmp(&m->o, &r->o, sizeof m->o) == 0 &&
      toward_area(&acc->areas[m->area], m->from, r, tmax))
    return m;
  if (!(tmax < INFINITY))
    return NULL;
  for (int k = 0; k < acc->n_areas; k++) {
    vec3s from = area_from(&acc->areas[k], r->o);
    if (toward_area(&acc->areas[k], from, r, tmax)) {
      *m = (ShadowMemo){.accel = acc->id, .area = k, .o = r->o, .from = from};
      m->n = area_shapes(scene, acc, r->o, acc->areas[k].quad, m->ids, VIEW_MAX);
      return m;
    }
  }
  return NULL;
}

static bool accel_any(const Scene *scene, const Ray *r, float tmax)
{
  const Accel *acc = (const Accel *)scene->index;
  const ShadowMemo *m = acc->n_areas > 0 ? shadow_memo(scene, acc, r, tmax) : NULL;
  if (m && m->n >= 0) {
    for (int k = 0; k < m->n; k++) {
      const Instance *inst = &scene->instances[m->ids[k]];
      if (!leaves_plane(inst, r) && scene_instance_hit_t(inst, *r, tmax) < tmax)
        return true;
    }
    return false;
  }
  for (int k = 0; k < acc->n_others_lit; k++) {
    const Instance *inst = &scene->instances[acc->others[k]];
    if (!leaves_plane(inst, r) && scene_instance_hit_t(inst, *r, tmax) < tmax)
      return true;
  }
  uint32_t mask;
  if (acc->cones && cones_toward_light(acc->cones, r, tmax, &mask)) {
    for (const int *ids = cones_spheres(acc->cones); mask; mask &= mask - 1)
      if (scene_instance_hit_t(&scene->instances[ids[__builtin_ctz(mask)]], *r, tmax) < tmax)
        return true;
    return false;
  }
  return acc->nodes && bvh_any(scene, acc, r, tmax);
}

static void accel_destroy(Accel *acc)
{
  free(acc->nodes);
  free(acc->spheres);
  free(acc->boxes);
  free(acc->others);
  cones_free(acc->cones);
  free(acc);
}

/* ---------------------------------------------------------------- building */

/* Which layout RT_ACCEL asks for: 0 plain loop, 1 one leaf, 2 hierarchy,
 * -1 automatic. */
static int layout_wanted(void)
{
  const char *env = getenv("RT_ACCEL");
  if (!env || !*env)
    return -1;
  return strcmp(env, "loop") == 0 ? 0 : strcmp(env, "flat") == 0 ? 1
       : strcmp(env, "bvh") == 0  ? 2 : -1;
}

/* The sphere an instance of the hierarchy stands in: a sphere itself; any
 * other shape the ball around its box (scene_instance_bounds), which holds
 * its box's margin, the rounding of the ball's own centre and radius far
 * below it. */
static Sphere item_sphere(const Instance *inst)
{
  if (inst->shape == SHAPE_SPHERE)
    return inst->sphere;
  Box b = scene_instance_bounds(inst);
  vec3s half = glms_vec3_scale(glms_vec3_sub(b.max, b.min), 0.5f);
  return (Sphere){.center = glms_vec3_add(b.min, half),
                  .radius = glms_vec3_norm(half) * (1.0f + 0x1p-20f)};
}

/* An instance's ball as the build reads it (index/box.h). */
static Ball item_ball(const Instance *inst)
{
  Sphere s = item_sphere(inst);
  return (Ball){s.center.x, s.center.y, s.center.z, s.radius};
}

/* The hierarchy over the n shapes: instances base .. base + n - 1 (spheres,
 * read in place), or (base < 0) those whose indices are ids[], their balls
 * in balls[]. One leaf of all of them when `flat`, else binned SAH with
 * leaves of at most LEAF_MAX. Leaves list their shapes in instance order.
 * `shapes`: some are not spheres, whose boxes acc->boxes then keeps. */
static bool build_tree(const Scene *scene, Accel *acc, const int *ids, int base,
                       const Ball *balls, int n, bool flat, bool shapes)
{
  Bvh bvh = {0};
  Balls from = base >= 0 ? (Balls){(const char *)&scene->instances[base].sphere, sizeof(Instance)}
                         : (Balls){(const char *)balls, sizeof *balls};
  if (!bvh_build(&bvh, from, n, flat ? n : LEAF_MAX))
    return false;
  acc->spheres = bvh.order; /* leaf order, as indices into ids: map them */
#pragma omp parallel for schedule(static) if (n > 65536)
  for (int k = 0; k < n; k++)
    acc->spheres[k] = base >= 0 ? base + acc->spheres[k] : ids[acc->spheres[k]];
  acc->nodes = bvh.nodes;
  if (!shapes)
    return true;
  acc->boxes = malloc((size_t)n * sizeof *acc->boxes);
  for (int k = 0; acc->boxes && k < n; k++)
    acc->boxes[k] = scene_instance_bounds(&scene->instances[acc->spheres[k]]);
  return acc->boxes != NULL;
}

enum { BLOCKS_MAX = 256 }; /* blocks of instances sorted at once */

/* Whether instance k goes into the hierarchy: a lit shape with a bounded
 * box (every shape but the plane). The others (planes, the lights' shapes)
 * stay in the list. */
static bool tree_item(const Scene *scene, int k)
{
  if (k >= scene->n_shapes)
    return false;
  const Instance *inst = &scene->instances[k];
  return inst->shape == SHAPE_SPHERE ||
         (inst->shape != SHAPE_PLANE && box_is_bounded(scene_instance_bounds(inst)));
}

/* The hierarchy's shapes (tree_item) into ids[] (instance order) with their
 * balls, everything else into acc->others (instance order, so the lit ones
 * first); returns the hierarchy's count. Large scenes in blocks, one per thread: each block counted,
 * then filled at its place, so the lists are the same for any thread count
 * (the balls written with the ids, so that each instance is read twice, not
 * three times). *base: when a large scene's hierarchy is of spheres only,
 * the instances base, base + 1, ... (a file of spheres, its planes before or
 * after them),
 * ids[] and balls[] are left unwritten, sphere k being instance base + k,
 * which the build reads in place; else -1. The fill is then only that of the
 * few others: one pass over the instances instead of two, and no copy of
 * the spheres. */
static int sort_instances(const Scene *scene, Accel *acc, int *ids, Ball *balls, int *base,
                          bool *shapes_too)
{
  int n = scene->n_instances, threads = omp_get_max_threads();
  int blocks = n > 65536 ? (threads < BLOCKS_MAX ? threads : BLOCKS_MAX) : 1;
  int first[BLOCKS_MAX + 1], spheres[BLOCKS_MAX + 1], lo[BLOCKS_MAX], hi[BLOCKS_MAX];
  bool shapes[BLOCKS_MAX]; /* a shape other than a sphere among the block's */
  for (int b = 0; b <= blocks; b++)
    first[b] = (int)((long long)n * b / blocks);
#pragma omp parallel for schedule(static, 1) if (blocks > 1)
  for (int b = 0; b < blocks; b++) {
    int count = 0, low = INT_MAX, high = -1; /* in registers: the arrays share a cache line */
    bool other = false;
    for (int k = first[b]; k < first[b + 1]; k++)
      if (tree_item(scene, k)) {
        count++;
        low = low < k ? low : k;
        high = k;
        other = other || scene->instances[k].shape != SHAPE_SPHERE;
      }
    spheres[b] = count;
    lo[b] = low;
    hi[b] = high;
    shapes[b] = other;
  }
  int sum = 0, lo_all = INT_MAX, hi_all = -1;
  bool other = false;
  for (int b = 0; b < blocks; b++) { /* spheres[b]: where block b's go */
    int count = spheres[b];
    spheres[b] = sum;
    sum += count;
    lo_all = lo[b] < lo_all ? lo[b] : lo_all;
    hi_all = hi[b] > hi_all ? hi[b] : hi_all;
    other = other || shapes[b];
  }
  spheres[blocks] = sum;
  *base = blocks > 1 && sum > 0 && !other && hi_all - lo_all + 1 == sum ? lo_all : -1;
  *shapes_too = other;
  acc->n_others = n - sum;
  if (*base >= 0) { /* the spheres are read in place: the others are before and after them */
    int o = 0;
    for (int k = 0; k < *base; k++)
      acc->others[o++] = k;
    for (int k = *base + sum; k < n; k++)
      acc->others[o++] = k;
  } else {
#pragma omp parallel for schedule(static, 1) if (blocks > 1)
    for (int b = 0; b < blocks; b++) {
      int s = spheres[b], o = first[b] - spheres[b];
      for (int k = first[b]; k < first[b + 1]; k++) {
        if (tree_item(scene, k)) {
          balls[s] = item_ball(&scene->instances[k]);
          ids[s++] = k;
        } else {
          acc->others[o++] = k;
        }
      }
    }
  }
  while (acc->n_others_lit < acc->n_others && acc->others[acc->n_others_lit] < scene->n_shapes)
    acc->n_others_lit++;
  return sum;
}

/* More light samples than this: the shadow rays toward area lights test
 * only the shapes that may stop them. Fewer: the hull costs more than it
 * saves. */
enum { SHADOW_VIEW_MIN_SAMPLES = 4 };

/* The area lights' recognition data (Area). */
static void add_areas(const Scene *scene, Accel *acc)
{
  if (scene->light_samples <= SHADOW_VIEW_MIN_SAMPLES)
    return;
  for (int k = 0; k < scene->n_lights && acc->n_areas < AREAS_MAX; k++) {
    const Quad *q = &scene->lights[k].quad;
    if (scene->lights[k].type != LIGHT_AREA || !(q->area > 0.0f))
      continue;
    vec3s n = q->normal, c1 = glms_vec3_cross(q->edge2, n), c2 = glms_vec3_cross(n, q->edge1);
    float d1 = glms_vec3_dot(q->edge1, c1), d2 = glms_vec3_dot(q->edge2, c2);
    if (!(fabsf(d1) > 0.0f && fabsf(d2) > 0.0f))
      continue;
    acc->areas[acc->n_areas++] = (Area){
        .quad = q, .corner = q->corner, .normal = n,
        .u1 = glms_vec3_scale(c1, 1.0f / d1), .u2 = glms_vec3_scale(c2, 1.0f / d2),
        .stray = 0x1p-19f * (vec_max_abs(q->corner) + vec_max_abs(q->edge1) +
                             vec_max_abs(q->edge2)),
        .per_edges = 1.0f / (glms_vec3_norm(q->edge1) + glms_vec3_norm(q->edge2))};
  }
}

void accel_free(Scene *scene)
{
  if (scene->index && scene->index->any == accel_any)
    accel_destroy((Accel *)scene->index);
  scene->index = NULL;
}

bool accel_build(Scene *scene)
{
  accel_free(scene);
  int layout = layout_wanted();
  if (layout == 0)
    return true;
  Accel *acc = calloc(1, sizeof *acc);
  size_t room = (size_t)scene->n_instances + 1;
  int *ids = malloc(room * sizeof *ids);
  Ball *balls = malloc(room * sizeof *balls); /* pages past the spheres' stay untouched */
  if (acc)
    acc->others = malloc(room * sizeof *acc->others);
  bool ok = acc && ids && balls && acc->others;
  int base = -1;
  bool shapes = false;
  int n = ok ? sort_instances(scene, acc, ids, balls, &base, &shapes) : 0;
  if (ok && n > 0)
    ok = build_tree(scene, acc, ids, base, balls, n,
                    layout == 1 || (layout < 0 && n <= ACCEL_FLAT_MAX), shapes);
  free(balls);
  if (ok && layout < 0 && n <= ACCEL_FLAT_MAX) {
    Sphere bounds[ACCEL_FLAT_MAX];
    for (int k = 0; k < n; k++) {
      if (base >= 0) /* a few spheres among 65 536 other shapes */
        ids[k] = base + k;
      bounds[k] = item_sphere(&scene->instances[ids[k]]);
    }
    acc->cones = cones_build(scene, ids, bounds, n); /* NULL: the rays go to the leaf */
  }
  free(ids);
  if (!ok) {
    fprintf(stderr, "accel: out of memory for %d instances\n", scene->n_instances);
    if (acc)
      accel_destroy(acc);
    return false;
  }
  static unsigned builds; /* Accel.id: never 0, never that of an index still alive */
  acc->id = __atomic_add_fetch(&builds, 1, __ATOMIC_RELAXED);
  add_areas(scene, acc);
  acc->base = (SceneIndex){.closest = accel_closest, .any = accel_any};
  scene->index = &acc->base;
  return true;
}

/* ---------------------------------------------------------------- shadow volume */

/* Shadow-volume queries: the lit shapes that may stop a shadow ray. */
typedef struct Occluders {
  int *ids, n, max; /* ids[0 .. n-1] found so far; more than max: give up */
} Occluders;

/* Record instance `id`; false when that makes more than o->max. */
static bool occluder(Occluders *o, int id)
{
  if (o->n == o->max)
    return false;
  o->ids[o->n++] = id;
  return true;
}

/* Whether a lit shape may stop a ray of the hull: a sphere or a plane by
 * its own test (hull.c), any other shape by its box, which then may occlude
 * only the rays that pass through it. */
static bool instance_may_occlude(const Instance *inst, const ShadowHull *h)
{
  switch (inst->shape) {
  case SHAPE_SPHERE: return hull_may_meet_sphere(h, inst->sphere.center, inst->sphere.radius);
  case SHAPE_PLANE: return hull_may_meet_plane(h, &inst->plane);
  default: {
    Box b = scene_instance_bounds(inst);
    return !box_is_bounded(b) || hull_may_meet_box(h, b.min.raw, b.max.raw);
  }
  }
}

/* The traversal of bvh_any, with boxes and shapes tested against the hull
 * (a sphere by its own test, any other shape by its box, as
 * instance_may_occlude does);
 * false when more than o->max shapes may meet it. */
static bool bvh_occluders(const Scene *scene, const Accel *acc, const ShadowHull *h,
                          Occluders *o)
{
  int stack[STACK], top = 0, node = 0;
  for (;;) {
    const BvhNode *nd = &acc->nodes[node];
    if (hull_may_meet_box(h, nd->lo, nd->hi)) {
      if (nd->meta > 0) {
        for (int k = nd->index; k < nd->index + nd->meta; k++) {
          const Instance *inst = &scene->instances[acc->spheres[k]];
          bool may = inst->shape == SHAPE_SPHERE
                         ? hull_may_meet_sphere(h, inst->sphere.center, inst->sphere.radius)
                         : hull_may_meet_box(h, acc->boxes[k].min.raw, acc->boxes[k].max.raw);
          if (may && !occluder(o, acc->spheres[k]))
            return false;
        }
      } else {
        stack[top++] = nd->index + 1;
        node = nd->index;
        continue;
      }
    }
    if (top == 0)
      return true;
    node = stack[--top];
  }
}


/* The lit shapes that may stop a ray from o to the quad (hull.c's tests,
 * through the hierarchy's boxes): their count and instance indices in ids,
 * or -1 when more than max may. Every other lit shape lets every such ray
 * pass: scene_occluded over ids alone answers as over the whole scene.
 * Not inlined: it runs once per shading point and light. */
__attribute__((noinline)) static int area_shapes(const Scene *scene, const Accel *acc, vec3s o,
                                                 const Quad *q, int *ids, int max)
{
  ShadowHull h = hull_make(o, q);
  Occluders oc = {.ids = ids, .max = max};
  for (int k = 0; k < acc->n_others_lit; k++)
    if (instance_may_occlude(&scene->instances[acc->others[k]], &h) &&
        !occluder(&oc, acc->others[k]))
      return -1;
  return acc->nodes && !bvh_occluders(scene, acc, &h, &oc) ? -1 : oc.n;
}

int accel_area_shapes(const Scene *scene, vec3s o, const Quad *q, int *ids, int max)
{
  return area_shapes(scene, (const Accel *)scene->index, o, q, ids, max);
}
