/* Building the acceleration structure (docs/performance.md): lit spheres
 * sorted into blocks of LANES, bounded, and put under a BVH (common/bvh.c)
 * when there are more than ACCEL_FLAT_MAX of them. The queries are in accel.c. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel_layout.h"

/* Which layout RT_ACCEL asks for: 0 plain loop, 1 flat blocks, 2 hierarchy,
 * -1 automatic. */
static int layout_wanted(void)
{
  const char *env = getenv("RT_ACCEL");
  if (!env || !*env)
    return -1;
  return strcmp(env, "loop") == 0 ? 0 : strcmp(env, "flat") == 0 ? 1
       : strcmp(env, "bvh") == 0  ? 2 : -1;
}

/* Fill blocks with the spheres listed in `order` (instance indices), `per`
 * spheres per block except possibly the last. */
static void fill_blocks(SphereBlock *blocks, const Scene *scene, const int *order,
                        int n)
{
  for (int k = 0; k < n; k++) {
    SphereBlock *blk = &blocks[k / LANES];
    const Sphere *s = &scene->instances[order[k]].sphere;
    blk->cx[k % LANES] = s->center.x;
    blk->cy[k % LANES] = s->center.y;
    blk->cz[k % LANES] = s->center.z;
    blk->rad[k % LANES] = s->radius;
    blk->inst[k % LANES] = order[k];
  }
}

/* Each block's bounding sphere: centred on the box of its spheres, radius
 * the farthest sphere's |c_k - centre| + r_k, rounded up by 2^-20 relative. */
static void bound_blocks(SphereBlock *blocks, int n_blocks)
{
  for (int k = 0; k < n_blocks; k++) {
    SphereBlock *blk = &blocks[k];
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int lane = 0; lane < LANES && blk->inst[lane] != INT_MAX; lane++) {
      float c[3] = {blk->cx[lane], blk->cy[lane], blk->cz[lane]};
      for (int a = 0; a < 3; a++) {
        lo[a] = fminf(lo[a], c[a] - blk->rad[lane]);
        hi[a] = fmaxf(hi[a], c[a] + blk->rad[lane]);
      }
    }
    blk->bound_c = vec_make(0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]), 0.5f * (lo[2] + hi[2]));
    double radius = 0.0;
    for (int lane = 0; lane < LANES && blk->inst[lane] != INT_MAX; lane++) {
      double dx = (double)blk->cx[lane] - blk->bound_c.x, dy = (double)blk->cy[lane] - blk->bound_c.y,
             dz = (double)blk->cz[lane] - blk->bound_c.z;
      double reach = sqrt(dx * dx + dy * dy + dz * dz) + blk->rad[lane];
      radius = reach > radius ? reach : radius;
    }
    radius *= 1.0 + 0x1p-20;
    blk->bound_r2 = (float)(radius * radius * (1.0 + 0x1p-20));
  }
}

static SphereBlock *blocks_alloc(int n_blocks)
{
  SphereBlock *blocks = aligned_alloc(32, (size_t)n_blocks * sizeof *blocks);
  for (int k = 0; blocks && k < n_blocks; k++)
    for (int lane = 0; lane < LANES; lane++) {
      blocks[k].cx[lane] = blocks[k].cy[lane] = blocks[k].cz[lane] = NAN;
      blocks[k].rad[lane] = 0.0f;
      blocks[k].inst[lane] = INT_MAX;
    }
  return blocks;
}

/* The hierarchy over the spheres `ids`: one block per leaf. Boxes are padded
 * by a relative 2^-16 of the radius and 2^-20 of the coordinates' magnitude so
 * that a grazing ray the sphere test accepts is never culled by its box. */
static bool build_tree(struct SceneAccel *acc, const Scene *scene, const int *ids, int n)
{
  float(*lo)[3] = malloc((size_t)n * sizeof *lo), (*hi)[3] = malloc((size_t)n * sizeof *hi);
  Bvh bvh = {0};
  bool ok = lo && hi;
  for (int k = 0; ok && k < n; k++) {
    const Sphere *s = &scene->instances[ids[k]].sphere;
    float pad = 0x1p-16f * s->radius + 0x1p-20f * (vec_max_abs(s->center) + s->radius);
    for (int a = 0; a < 3; a++) {
      lo[k][a] = s->center.raw[a] - s->radius - pad;
      hi[k][a] = s->center.raw[a] + s->radius + pad;
    }
  }
  ok = ok && bvh_build(&bvh, (const float(*)[3])lo, (const float(*)[3])hi, n, LANES);
  free(lo);
  free(hi);
  int leaves = 0;
  for (int k = 0; ok && k < bvh.n_nodes; k++)
    leaves += bvh.nodes[k].meta > 0;
  acc->blocks = ok ? blocks_alloc(leaves) : NULL;
  if (!acc->blocks) {
    bvh_free(&bvh);
    return false;
  }
  int *order = malloc(LANES * sizeof *order);
  for (int k = 0, leaf = 0; order && k < bvh.n_nodes; k++) {
    BvhNode *nd = &bvh.nodes[k];
    if (nd->meta <= 0)
      continue;
    for (int m = 0; m < nd->meta; m++) { /* insertion sort: lanes in instance order */
      int id = ids[bvh.order[nd->index + m]], at = m;
      for (; at > 0 && order[at - 1] > id; at--)
        order[at] = order[at - 1];
      order[at] = id;
    }
    fill_blocks(&acc->blocks[leaf], scene, order, nd->meta);
    nd->index = leaf++;
  }
  ok = order != NULL;
  free(order);
  acc->n_blocks = leaves;
  acc->nodes = bvh.nodes;
  bvh.nodes = NULL;
  bvh_free(&bvh);
  return ok;
}

/* Split the instances into lit spheres (ids) and the rest (acc->others, lit
 * ones first). Returns the number of spheres, -1 when out of memory. */
static int sort_instances(struct SceneAccel *acc, const Scene *scene, int **ids)
{
  int n = 0;
  *ids = malloc((size_t)(scene->n_instances + 1) * sizeof **ids);
  acc->others = malloc((size_t)(scene->n_instances + 1) * sizeof *acc->others);
  if (!*ids || !acc->others)
    return -1;
  for (int k = 0; k < scene->n_instances; k++) {
    if (k < scene->n_shapes && scene->instances[k].shape == SHAPE_SPHERE)
      (*ids)[n++] = k;
    else
      acc->others[acc->n_others++] = k;
    if (k < scene->n_shapes)
      acc->n_others_lit = acc->n_others;
  }
  return n;
}

bool accel_build(Scene *scene)
{
  accel_free(scene);
  int layout = layout_wanted();
  if (layout == 0)
    return true;
  struct SceneAccel *acc = calloc(1, sizeof *acc);
  int *ids = NULL;
  int n = acc ? sort_instances(acc, scene, &ids) : -1;
  bool ok = n >= 0;
  if (ok && (layout == 2 || (layout < 0 && n > ACCEL_FLAT_MAX)) && n > 0) {
    ok = build_tree(acc, scene, ids, n);
  } else if (ok) {
    acc->n_blocks = (n + LANES - 1) / LANES;
    acc->blocks = blocks_alloc(acc->n_blocks > 0 ? acc->n_blocks : 1);
    ok = acc->blocks != NULL;
    if (ok) {
      fill_blocks(acc->blocks, scene, ids, n);
      bound_blocks(acc->blocks, acc->n_blocks);
    }
  }
  free(ids);
  scene->accel = acc;
  if (!ok) {
    fprintf(stderr, "accel: out of memory for %d instances\n", scene->n_instances);
    accel_free(scene);
  }
  return ok;
}

void accel_free(Scene *scene)
{
  struct SceneAccel *acc = scene->accel;
  if (acc) {
    free(acc->blocks);
    free(acc->nodes);
    free(acc->others);
    free(acc);
  }
  scene->accel = NULL;
}
