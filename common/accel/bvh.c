/* BVH build (docs/performance.md): top-down, each node split where the binned
 * surface area heuristic says a ray pays least, i.e. minimising
 *   C_trav + (A_left / A) cost(left) + (A_right / A) cost(right),
 * with a leaf of n items costing n C_item (each item is tested on its own). */
#include "accel/bvh.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>

enum { BINS = 16, MAX_DEPTH = 40 };
static const float COST_TRAV = 1.0f, COST_ITEM = 1.5f;

typedef struct Box {
  float lo[3], hi[3];
} Box;

typedef struct Build {
  const float (*lo)[3], (*hi)[3];
  float (*cen)[3]; /* box centres (twice the centre: lo + hi, exact enough to bin) */
  int *order;
  BvhNode *nodes;
  int n_nodes, n_items, leaf_max;
} Build;

static Box box_empty(void)
{
  return (Box){{FLT_MAX, FLT_MAX, FLT_MAX}, {-FLT_MAX, -FLT_MAX, -FLT_MAX}};
}

static void box_grow(Box *b, const float lo[3], const float hi[3])
{
  for (int a = 0; a < 3; a++) {
    b->lo[a] = lo[a] < b->lo[a] ? lo[a] : b->lo[a];
    b->hi[a] = hi[a] > b->hi[a] ? hi[a] : b->hi[a];
  }
}

/* Half the surface area (the factor 2 cancels in every ratio). */
static float box_area(const Box *b)
{
  float dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
  return dx < 0.0f ? 0.0f : dx * dy + dy * dz + dz * dx;
}

static float leaf_cost(int count)
{
  return COST_ITEM * (float)count;
}

/* Clamped before the conversion: a huge or NaN product (overflowing bounds)
 * lands in a boundary bin instead of being converted out of int's range. */
static int bin_of(float c, float lo, float scale)
{
  float x = (c - lo) * scale;
  return x >= (float)(BINS - 1) ? BINS - 1 : x > 0.0f ? (int)x : 0;
}

/* The best binned split of items [first, first + count): its cost, axis and
 * bin boundary (items with bin < *split_bin go left). */
static float best_split(const Build *b, int first, int count, const Box *cb,
                        float area, int *axis, int *split_bin)
{
  float best = FLT_MAX;
  for (int a = 0; a < 3; a++) {
    float extent = cb->hi[a] - cb->lo[a];
    if (!(extent > 0.0f))
      continue;
    float scale = (float)BINS / extent;
    Box bins[BINS];
    int n[BINS] = {0};
    for (int k = 0; k < BINS; k++)
      bins[k] = box_empty();
    for (int k = first; k < first + count; k++) {
      int item = b->order[k], bin = bin_of(b->cen[item][a], cb->lo[a], scale);
      n[bin]++;
      box_grow(&bins[bin], b->lo[item], b->hi[item]);
    }
    /* Sweep from the right, keeping suffix areas, then from the left. */
    float right_area[BINS];
    int right_n[BINS];
    Box acc = box_empty();
    int acc_n = 0;
    for (int k = BINS - 1; k > 0; k--) {
      box_grow(&acc, bins[k].lo, bins[k].hi);
      acc_n += n[k];
      right_area[k] = box_area(&acc);
      right_n[k] = acc_n;
    }
    acc = box_empty();
    acc_n = 0;
    for (int k = 1; k < BINS; k++) {
      box_grow(&acc, bins[k - 1].lo, bins[k - 1].hi);
      acc_n += n[k - 1];
      if (acc_n == 0 || right_n[k] == 0)
        continue;
      float cost = COST_TRAV + (box_area(&acc) * leaf_cost(acc_n) +
                                right_area[k] * leaf_cost(right_n[k])) / area;
      if (cost < best) {
        best = cost;
        *axis = a;
        *split_bin = k;
      }
    }
  }
  return best;
}

/* Split [first, first + count) in two; returns the first index of the right
 * half. Falls back to halving by count when the heuristic cannot separate
 * the items (all centres equal) or the tree is already deep (a pathological
 * distribution): depth stays below MAX_DEPTH + log2(n). */
static int partition(Build *b, int first, int count, const Box *cb, float area,
                     int depth, bool *leaf)
{
  int axis = 0, split_bin = 0;
  float cost = depth < MAX_DEPTH && count > 1
                   ? best_split(b, first, count, cb, area, &axis, &split_bin)
                   : FLT_MAX;
  *leaf = count <= b->leaf_max && !(cost < leaf_cost(count));
  if (*leaf)
    return first;
  if (cost < FLT_MAX) {
    float scale = (float)BINS / (cb->hi[axis] - cb->lo[axis]);
    int i = first, j = first + count - 1;
    while (i <= j) {
      if (bin_of(b->cen[b->order[i]][axis], cb->lo[axis], scale) < split_bin) {
        i++;
      } else {
        int tmp = b->order[i];
        b->order[i] = b->order[j];
        b->order[j--] = tmp;
      }
    }
    return i;
  }
  return first + count / 2;
}

static void build_node(Build *b, int node, int first, int count, int depth)
{
  Box box = box_empty(), cb = box_empty();
  for (int k = first; k < first + count; k++) {
    int item = b->order[k];
    box_grow(&box, b->lo[item], b->hi[item]);
    box_grow(&cb, b->cen[item], b->cen[item]);
  }
  BvhNode *nd = &b->nodes[node];
  for (int a = 0; a < 3; a++) {
    nd->lo[a] = box.lo[a];
    nd->hi[a] = box.hi[a];
  }
  bool leaf = count <= 1 || b->leaf_max >= b->n_items; /* one leaf of everything */
  int mid = leaf ? first : partition(b, first, count, &cb, box_area(&box), depth, &leaf);
  if (leaf) {
    nd->index = first;
    nd->meta = count;
    return;
  }
  int axis = 0;
  for (int a = 1; a < 3; a++)
    if (cb.hi[a] - cb.lo[a] > cb.hi[axis] - cb.lo[axis])
      axis = a;
  int child = b->n_nodes;
  b->n_nodes += 2;
  nd->index = child;
  nd->meta = -1 - axis;
  build_node(b, child, first, mid - first, depth + 1);
  build_node(b, child + 1, mid, first + count - mid, depth + 1);
}

bool bvh_build(Bvh *bvh, const float (*lo)[3], const float (*hi)[3], int n,
               int leaf_max)
{
  Build b = {.lo = lo, .hi = hi, .leaf_max = leaf_max, .n_nodes = 1, .n_items = n};
  b.cen = malloc((size_t)n * sizeof *b.cen);
  b.order = malloc((size_t)n * sizeof *b.order);
  b.nodes = malloc((size_t)(2 * n - 1) * sizeof *b.nodes);
  *bvh = (Bvh){0};
  if (!b.cen || !b.order || !b.nodes) {
    fprintf(stderr, "bvh: out of memory for %d boxes\n", n);
    free(b.cen);
    free(b.order);
    free(b.nodes);
    return false;
  }
  for (int k = 0; k < n; k++) {
    b.order[k] = k;
    for (int a = 0; a < 3; a++)
      b.cen[k][a] = lo[k][a] + hi[k][a];
  }
  build_node(&b, 0, 0, n, 0);
  free(b.cen);
  *bvh = (Bvh){.nodes = b.nodes, .n_nodes = b.n_nodes, .order = b.order, .n_items = n};
  return true;
}

void bvh_free(Bvh *bvh)
{
  free(bvh->nodes);
  free(bvh->order);
  *bvh = (Bvh){0};
}
