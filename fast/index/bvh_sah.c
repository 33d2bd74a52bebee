/* The binned surface area heuristic (docs/performance.md): each node split
 * where a ray pays least, i.e. minimising
 *   C_trav + (A_left / A) cost(left) + (A_right / A) cost(right),
 * with a leaf of n items costing n C_item (each item is tested on its own).
 * Items may be weighted (clusters of boxes, fast/index/bvh.c). */
#include "index/bvh_sah.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

enum {
  BINS = 16,
  MAX_DEPTH = 40,
  TASK_MIN = 8192,   /* subtrees of more (weighted) items are built as tasks */
};
static const float COST_TRAV = 1.0f, COST_ITEM = 1.5f;

/* Half the surface area (the factor 2 cancels in every ratio). */
static float box_area(const Box4 *b)
{
  float dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
  return dx < 0.0f ? 0.0f : dx * dy + dy * dz + dz * dx;
}

static float leaf_cost(int count)
{
  return COST_ITEM * (float)count;
}

/* The bin of twice a centre, c = lo + hi, on an axis starting at `lo` with
 * BINS / extent = `scale`. Clamped before the conversion: a huge or NaN
 * product lands in a boundary bin (NaN in bin 0) instead of being converted
 * out of int's range. */
static int bin_of(float c, float lo, float scale)
{
  float x = (c - lo) * scale;
  x = x > 0.0f ? x : 0.0f;
  return (int)(x < (float)(BINS - 1) ? x : (float)(BINS - 1));
}

/* How many boxes item k stands for. */
static int weight_of(const SahBuild *b, int k)
{
  return b->weight ? b->weight[k] : 1;
}

static float centre2(const Box4 *it, int a)
{
  return it->lo[a] + it->hi[a];
}

/* bin_of on the three axes at once (scale's 4th lane is 0: bin 0). */
static I4 bins_of(const Box4 *it, const Box4 *cb, V4 scale)
{
  V4 x = (it->lo + it->hi - cb->lo) * scale, zero = {0.0f, 0.0f, 0.0f, 0.0f};
  V4 top = {BINS - 1, BINS - 1, BINS - 1, BINS - 1};
  I4 m = x > zero;
  x = (V4)(m & (I4)x);
  return __builtin_convertvector(v4_min(x, top), I4);
}

/* Keep the split at bin boundary k of axis a when it is the cheapest yet. */
static void consider(float cost, int a, int k, float *best, int *axis, int *split_bin)
{
  if (cost < *best) {
    *best = cost;
    *axis = a;
    *split_bin = k;
  }
}

/* The cheapest bin boundary of items [first, first + count) on each axis.
 * Each item is binned once on the three axes (bins_of); a bin is started
 * when its first item comes (`used`). Then, axis by axis, a sweep from the
 * right keeps the suffix bounds, and one from the left prices each boundary
 * between two non-empty bins: the boundaries between the same two
 * non-empty bins split the items alike, so the first of them stands for
 * all (a strictly lower cost wins), and small nodes pay for the bins they
 * use, not for 16 an axis. */
static void sweep_bins(const SahBuild *b, int first, int count, const Box4 *cb, V4 scale,
                       float area, float *best, int *axis, int *split_bin)
{
  Box4 box[3][BINS];
  int n[3][BINS];
  uint32_t used[3] = {0, 0, 0};
  for (int k = first; k < first + count; k++) {
    const Box4 *it = &b->items[k];
    I4 bin = bins_of(it, cb, scale);
    int w = weight_of(b, k);
    for (int a = 0; a < 3; a++) {
      int v = bin[a];
      if (!(used[a] >> v & 1u)) {
        used[a] |= 1u << v;
        box[a][v] = box4_empty();
        n[a][v] = 0;
      }
      box4_grow(&box[a][v], it);
      n[a][v] += w;
    }
  }
  for (int a = 0; a < 3; a++) {
    if (scale[a] == 0.0f || (used[a] & (used[a] - 1)) == 0)
      continue; /* one bin: no boundary between two non-empty ones */
    int last[BINS], right_n[BINS], groups = 0;
    Box4 right[BINS];
    for (uint32_t m = used[a]; m; m &= m - 1)
      last[groups++] = __builtin_ctz(m);
    Box4 acc = box4_empty();
    int acc_n = 0;
    for (int g = groups - 1; g > 0; g--) {
      box4_grow(&acc, &box[a][last[g]]);
      acc_n += n[a][last[g]];
      right[g] = acc;
      right_n[g] = acc_n;
    }
    acc = box4_empty();
    acc_n = 0;
    for (int g = 1; g < groups; g++) {
      box4_grow(&acc, &box[a][last[g - 1]]);
      acc_n += n[a][last[g - 1]];
      consider(COST_TRAV + (box_area(&acc) * leaf_cost(acc_n) +
                            box_area(&right[g]) * leaf_cost(right_n[g])) / area,
               a, last[g - 1] + 1, best, axis, split_bin);
    }
  }
}

/* The best binned split of items [first, first + count): its cost, axis and
 * bin boundary (items with bin < *split_bin go left). */
static float best_split(const SahBuild *b, int first, int count, const Box4 *cb,
                        float area, int *axis, int *split_bin)
{
  float best = FLT_MAX;
  V4 scale = {0.0f, 0.0f, 0.0f, 0.0f};
  for (int a = 0; a < 3; a++) {
    float extent = cb->hi[a] - cb->lo[a];
    scale[a] = extent > 0.0f ? (float)BINS / extent : 0.0f;
  }
  sweep_bins(b, first, count, cb, scale, area, &best, axis, split_bin);
  return best;
}

/* The two halves of a split node: where the right one starts, the axis
 * along which the left one is the lower (-1: none, the items halved by
 * count), and each half's bounds, bounds of centres (c = lo + hi) and
 * weighted count. */
typedef struct Halves {
  int mid, axis;
  Box4 box[2], cb[2];
  int weight[2];
} Halves;

static void halves_empty(Halves *h)
{
  for (int s = 0; s < 2; s++) {
    h->box[s] = h->cb[s] = box4_empty();
    h->weight[s] = 0;
  }
}

/* Count item k into half s. */
static void halves_add(Halves *h, int s, const SahBuild *b, int k)
{
  const Box4 *it = &b->items[k];
  Box4 c = {it->lo + it->hi, it->lo + it->hi};
  box4_grow(&h->box[s], it);
  box4_grow(&h->cb[s], &c);
  h->weight[s] += weight_of(b, k);
}

/* Items i and j trade places (with their ids and weights). */
static void swap_items(SahBuild *b, int i, int j)
{
  Box4 tmp = b->items[i];
  int id = b->ids[i];
  b->items[i] = b->items[j];
  b->ids[i] = b->ids[j];
  b->items[j] = tmp;
  b->ids[j] = id;
  if (b->weight) {
    int w = b->weight[i];
    b->weight[i] = b->weight[j];
    b->weight[j] = w;
  }
}

int sah_apart_axis(const Box4 *a, const Box4 *b, bool *b_lower)
{
  V4 apart = (b->lo + b->hi) - (a->lo + a->hi);
  int axis = 0;
  for (int k = 1; k < 3; k++)
    if (fabsf(apart[k]) > fabsf(apart[axis]))
      axis = k;
  *b_lower = apart[axis] < 0.0f;
  return axis;
}

/* Move the items of bin < split_bin on `axis` to the front, measuring the
 * two halves on the way (each item is looked at once). */
static void split_items(SahBuild *b, int first, int count, const Box4 *cb, int axis,
                        int split_bin, Halves *h)
{
  float scale = (float)BINS / (cb->hi[axis] - cb->lo[axis]);
  int i = first, j = first + count - 1;
  halves_empty(h);
  while (i <= j) {
    if (bin_of(centre2(&b->items[i], axis), cb->lo[axis], scale) < split_bin) {
      halves_add(h, 0, b, i);
      i++;
    } else {
      swap_items(b, i, j);
      halves_add(h, 1, b, j);
      j--;
    }
  }
  h->mid = i;
}

/* Split [first, first + count) in two (h: the halves); false when it
 * stays a leaf. Falls back to halving by count when the heuristic cannot
 * separate the items (all centres equal) or the tree is already deep (a
 * pathological distribution): depth stays below MAX_DEPTH + log2(n). */
/* Two items that must be split (a build whose leaves hold one): each alone,
 * the lower first along the axis where their centres lie furthest apart.
 * The heuristic has nothing to choose there (either axis that separates them
 * gives the same two boxes); this skips its bins. */
static void split_pair(SahBuild *b, int first, Halves *h)
{
  bool second_lower;
  int axis = sah_apart_axis(&b->items[first], &b->items[first + 1], &second_lower);
  if (second_lower)
    swap_items(b, first, first + 1);
  halves_empty(h);
  halves_add(h, 0, b, first);
  halves_add(h, 1, b, first + 1);
  h->mid = first + 1;
  h->axis = axis;
}

static bool partition(SahBuild *b, int first, int count, const Box4 *cb, float area,
                      int depth, Halves *h)
{
  if (count == 2 && b->leaf_max < 2) {
    split_pair(b, first, h);
    return true;
  }
  int axis = 0, split_bin = 0;
  float cost = depth < MAX_DEPTH && count > 1
                   ? best_split(b, first, count, cb, area, &axis, &split_bin)
                   : FLT_MAX;
  if (count <= b->leaf_max && !(cost < leaf_cost(count)))
    return false;
  if (cost < FLT_MAX) {
    split_items(b, first, count, cb, axis, split_bin, h);
    h->axis = axis;
    return true;
  }
  halves_empty(h);
  h->axis = -1;
  h->mid = first + count / 2;
  for (int k = first; k < first + count; k++)
    halves_add(h, k >= h->mid, b, k);
  return true;
}

/* sah_build_node, with the items' bounds `box` and their centres' `cb`
 * (measured by the parent's split). */
static void build_node(SahBuild *b, int node, int first, int count, int depth, int block,
                       const Box4 *box, const Box4 *cb)
{
  Halves h;
  bool leaf = count <= 1 || b->one_leaf ||
              !partition(b, first, count, cb, box_area(box), depth, &h);
  if (leaf && b->weight) { /* one cluster or group: the caller fills the node */
    b->leaf_node[first] = node;
    if (b->leaf_depth)
      b->leaf_depth[first] = depth;
    return;
  }
  if (leaf) {
    b->nodes[node] = node_make(box, first, count);
    return;
  }
  /* The axis the traversal orders the children by (nearer first): the
   * split's, along which the left child is the lower; for a split by count,
   * the longest of the centres' bounds. */
  int axis = h.axis;
  if (axis < 0) {
    axis = 0;
    for (int a = 1; a < 3; a++)
      if (cb->hi[a] - cb->lo[a] > cb->hi[axis] - cb->lo[axis])
        axis = a;
  }
  b->nodes[node] = node_make(box, block, -1 - axis);
  int lc = h.mid - first, lw = h.weight[0];
  if (lw > TASK_MIN) {
#pragma omp task default(none) firstprivate(b, block, first, lc, depth, h)
    build_node(b, block, first, lc, depth + 1, block + 2, &h.box[0], &h.cb[0]);
  } else {
    build_node(b, block, first, lc, depth + 1, block + 2, &h.box[0], &h.cb[0]);
  }
  build_node(b, block + 1, h.mid, count - lc, depth + 1, block + 2 * lc, &h.box[1],
             &h.cb[1]);
}

void sah_build_node(SahBuild *b, int node, int first, int count, int depth, int block)
{
  Box4 box = box4_empty(), cb = box4_empty();
  for (int k = first; k < first + count; k++) {
    const Box4 *it = &b->items[k];
    Box4 c = {it->lo + it->hi, it->lo + it->hi};
    box4_grow(&box, it);
    box4_grow(&cb, &c);
  }
  build_node(b, node, first, count, depth, block, &box, &cb);
}
