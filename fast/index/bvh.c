/* BVH build (docs/performance.md): the binned surface area heuristic of
 * fast/index/bvh_sah.c over the balls' cubes. Above CLUSTER_FROM balls it
 * runs twice: the balls sorted along a Morton curve are cut into clusters of
 * at most CLUSTER neighbours, each cluster's subtree is built over its own
 * balls, then the heuristic builds the tree over the clusters' bounds (over
 * groups of them first, then inside each group): a tenth of the work of one
 * build over 10^6 balls, for trees about as good. Large
 * subtrees are OpenMP tasks; the tree is the same for any thread count: each
 * subtree owns a fixed block of nodes. The blocks of one build over all the
 * balls keep unused slots (where a leaf holds several), squeezed out at the
 * end; the clustered build leaves none: the tree over the groups of
 * clusters takes the first slots, then each group's region holds what is
 * below it (build_clustered). */
#include "index/bvh.h"

#include <limits.h>
#include "threads.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "index/bvh_sah.h"
#include "index/morton.h"

enum {
  CLUSTER_FROM = 16384, /* fewer balls: one build over all of them */
  CLUSTER = 16,         /* most balls in a cluster */
  GROUP = 256,          /* most balls in a group of clusters */
  PREFETCH_CLUSTERS = 4 /* a cluster's balls are fetched while the 4th before it is built */
};

/* ---------------------------------------------------------------- the build */

/* Renumber the subtree at old[node] into out[at], children pairs in the
 * order a depth-first build hands them out. *next: the next free slot. */
static void compact(const BvhNode *old, int node, BvhNode *out, int at, int *next)
{
  out[at] = old[node];
  if (old[node].meta > 0)
    return;
  int pair = *next;
  *next += 2;
  out[at].index = pair;
  compact(old, old[node].index, out, pair, next);
  compact(old, old[node].index + 1, out, pair + 1, next);
}

static int count_nodes(const BvhNode *old, int node)
{
  return old[node].meta > 0 ? 1 : 1 + count_nodes(old, old[node].index) +
                                      count_nodes(old, old[node].index + 1);
}

/* Squeeze the unused slots out of b->nodes; *n_nodes the count left. */
static bool squeeze(BvhNode **nodes, int n, int *n_nodes)
{
  *n_nodes = count_nodes(*nodes, 0);
  if (*n_nodes == 2 * n - 1)
    return true; /* no unused slot: already the depth-first numbering */
  BvhNode *dense = malloc((size_t)*n_nodes * sizeof *dense);
  if (!dense)
    return false;
  int next = 1;
  compact(*nodes, 0, dense, 0, &next);
  free(*nodes);
  *nodes = dense;
  return true;
}

/* Leaves of a cluster's subtree over `count` balls (cluster_node's halving
 * down to at most leaf_max balls a leaf): the subtree has 2 leaves - 1 nodes. */
static int cluster_leaves(int count, int leaf_max)
{
  return count <= leaf_max ? 1 : cluster_leaves(count / 2, leaf_max) +
                                 cluster_leaves(count - count / 2, leaf_max);
}

/* Two ids in increasing order, without a branch. */
static void order_pair(int *a, int *b)
{
  int lo = *a < *b ? *a : *b, hi = *a < *b ? *b : *a;
  *a = lo;
  *b = hi;
}

/* A leaf's ids in increasing order. Up to 4 (the hierarchy's leaves) by a
 * sorting network without branches: Morton order puts a 2 x 2 block's ids
 * in an order the branches of an insertion sort mispredicted, and its swaps
 * reloaded what they had just stored (about a fifth of cluster_node's
 * samples in `perf`); more by insertion. */
static void sort_leaf(int *ids, int count)
{
  if (count > 4) {
    for (int i = 1; i < count; i++)
      for (int j = i; j > 0 && ids[j - 1] > ids[j]; j--) {
        int id = ids[j];
        ids[j] = ids[j - 1];
        ids[j - 1] = id;
      }
    return;
  }
  int v[4] = {INT_MAX, INT_MAX, INT_MAX, INT_MAX};
  memcpy(v, ids, (size_t)count * sizeof *ids);
  order_pair(&v[0], &v[1]);
  order_pair(&v[2], &v[3]);
  order_pair(&v[0], &v[2]);
  order_pair(&v[1], &v[3]);
  order_pair(&v[1], &v[2]);
  memcpy(ids, v, (size_t)count * sizeof *ids);
}

/* The subtree of a cluster's balls ids[first .. first + count) (at most
 * CLUSTER neighbours in Morton order), halved by count down to leaves of at
 * most b->leaf_max balls (ids in increasing order): its descendants written
 * from slot `block` on (the first half's below the pair, then the second
 * half's), its root returned for the caller to place. Built from the leaves
 * up, each ball read once: a node's bounds are its children's. Cheap, and
 * for so few balls about as good as the heuristic (the two trees'
 * surface-area costs are nearly equal). A node's axis is the one along
 * which its halves' boxes lie furthest apart (their middles compared), the
 * lower half in the first slot of the pair: the traversal visits the nearer
 * child first by that axis. */
static BvhNode cluster_node(SahBuild *b, Balls balls, int first, int count, int block)
{
  if (count <= b->leaf_max) { /* the ids in increasing order */
    sort_leaf(b->ids + first, count);
    Box4 box = box4_empty();
    for (int k = first; k < first + count; k++) {
      Box4 it = ball_box(balls_get(balls, b->ids[k]));
      box4_grow(&box, &it);
    }
    return node_make(&box, first, count);
  }
  int lc = count / 2;
  BvhNode half[2] = {
      cluster_node(b, balls, first, lc, block + 2),
      cluster_node(b, balls, first + lc, count - lc,
                   block + 2 * cluster_leaves(lc, b->leaf_max))};
  Box4 box[2] = {node_box(&half[0]), node_box(&half[1])};
  bool second_lower; /* then the first half takes the second slot */
  int axis = sah_apart_axis(&box[0], &box[1], &second_lower);
  b->nodes[block + second_lower] = half[0];
  b->nodes[block + !second_lower] = half[1];
  box4_grow(&box[0], &box[1]);
  return node_make(&box[0], block, -1 - axis);
}

/* What a build over weighted boxes needs (clusters, or groups of them), one
 * array each (m entries). */
typedef struct Top {
  Box4 *boxes;
  int *ids, *weight, *leaf_node, *leaf_depth, *place, *first, *count;
} Top;

static bool top_alloc(Top *t, int m)
{
  t->boxes = malloc((size_t)m * sizeof *t->boxes);
  int **arrays[] = {&t->ids,   &t->weight, &t->leaf_node, &t->leaf_depth,
                    &t->place, &t->first,  &t->count};
  bool ok = t->boxes != NULL;
  for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
    ok = (*arrays[k] = malloc((size_t)m * sizeof(int))) != NULL && ok;
  return ok;
}

static void top_free(Top *t)
{
  free(t->boxes);
  int *arrays[] = {t->ids,   t->weight, t->leaf_node, t->leaf_depth,
                   t->place, t->first,  t->count};
  for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
    free(arrays[k]);
}

enum { CUT_PARTS = 256 }; /* most threads cutting clusters at once */

/* The clusters (Morton runs of at most CLUSTER balls) of every group (runs of
 * at most GROUP: each a whole number of clusters, since both are cut at the
 * same bits), the groups shared among the threads in consecutive parts:
 * each part's clusters written from its first ball's place in c->first and
 * c->count (a part has no more clusters than balls, and the pages touched
 * are those of its clusters), then the parts packed in order. The same
 * clusters for any number of threads. In g, each group's clusters g.first
 * .. g.first + g.count. */
static void cut_clusters(const uint64_t *sorted, const MortonRuns *gr, MortonRuns *c, Top *g)
{
  int at[CUT_PARTS], count[CUT_PARTS], parts = omp_get_max_threads();
  parts = parts < CUT_PARTS ? parts : CUT_PARTS;
#pragma omp parallel num_threads(parts)
  {
    int t = omp_get_thread_num(), used = omp_get_num_threads();
    int k0 = (int)((long long)gr->n * t / used), k1 = (int)((long long)gr->n * (t + 1) / used);
    at[t] = k0 < gr->n ? gr->first[k0] : 0;
    MortonRuns mine = {c->first + at[t], c->count + at[t], 0};
    for (int k = k0; k < k1; k++) {
      int before = mine.n;
      morton_runs(sorted, gr->first[k], gr->count[k], CLUSTER, &mine);
      g->count[k] = mine.n - before;
    }
    count[t] = mine.n;
#pragma omp single
    parts = used;
  }
  c->n = 0;
  for (int t = 0; t < parts; t++) { /* down: part t starts at or after c->n */
    memmove(c->first + c->n, c->first + at[t], (size_t)count[t] * sizeof(int));
    memmove(c->count + c->n, c->count + at[t], (size_t)count[t] * sizeof(int));
    c->n += count[t];
  }
  for (int k = 0, j = 0; k < gr->n; j += g->count[k++])
    g->first[k] = j;
}

/* Each group's bounds and weight, from its clusters' in t. */
static void group_clusters(const MortonRuns *gr, const Top *t, Top *g)
{
  for (int k = 0; k < gr->n; k++) {
    g->boxes[k] = box4_empty();
    g->weight[k] = 0;
    for (int j = g->first[k]; j < g->first[k] + g->count[k]; j++) {
      box4_grow(&g->boxes[k], &t->boxes[j]);
      g->weight[k] += t->weight[j];
    }
    g->ids[k] = k;
  }
}

/* Each cluster's subtree over its balls, then the tree over the clusters of
 * the balls in Morton order (b->ids, the sorted pairs `sorted`); *n_nodes the nodes
 * used. The tree over the clusters is built in two levels, as HLBVH does:
 * the heuristic over groups of clusters (GROUP neighbouring balls at most),
 * then in each group over its clusters, all groups at once (the heuristic
 * over every cluster spent most of its time near the top on one thread). A
 * cluster weighs its subtree's leaves in the heuristic, a group its
 * clusters'. The tree over the G groups takes slots 0 .. 2 G - 2; then, group
 * by group in Morton order, each group's region: its tree's descendants
 * (its root is a leaf of the tree over the groups), then its clusters'
 * descendants, cluster by cluster (a cluster's root is a leaf of its group's
 * tree). The regions depend on the counts only, so the clusters are built
 * first, at their place, and give the trees above them their bounds; and a
 * ray that enters a group finds what is below it in a few kilobytes. The
 * balls stay where they are: leaves index b->ids. */
static bool build_clustered(SahBuild *b, Balls balls, int n, const uint64_t *sorted,
                            int *n_nodes)
{
  int leaves = 0;
  MortonRuns c = {malloc((size_t)n * sizeof(int)), malloc((size_t)n * sizeof(int)), 0};
  MortonRuns gr = {malloc((size_t)n * sizeof(int)), malloc((size_t)n * sizeof(int)), 0};
  Top t = {0}, g = {0};
  bool ok = c.first && c.count && gr.first && gr.count;
  if (ok) { /* the groups (only the pages they write are touched), then their clusters */
    morton_runs(sorted, 0, n, GROUP, &gr);
    ok = top_alloc(&g, gr.n);
  }
  if (ok) {
    cut_clusters(sorted, &gr, &c, &g);
    ok = top_alloc(&t, c.n);
  }
  if (ok) { /* the sorted pairs (in the node array) are read no more */
    int per[CLUSTER + 1]; /* a cluster's leaves, by its count */
    for (int m = 0; m <= CLUSTER; m++)
      per[m] = cluster_leaves(m, b->leaf_max);
    for (int q = 0, block = 2 * gr.n - 1; q < gr.n; q++) { /* the regions */
      g.place[q] = block; /* the group's tree's descendants */
      block += 2 * g.count[q] - 2;
      for (int k = g.first[q]; k < g.first[q] + g.count[q]; k++) {
        t.weight[k] = per[c.count[k]];
        t.first[k] = block; /* the cluster's descendants */
        block += 2 * t.weight[k] - 2;
        leaves += t.weight[k];
      }
    }
#pragma omp parallel for schedule(dynamic, 256)
    for (int k = 0; k < c.n; k++) { /* the root kept in t: box, index, meta */
      if (k + PREFETCH_CLUSTERS < c.n) /* Morton order is not the balls': asked for ahead */
        for (int j = c.first[k + PREFETCH_CLUSTERS];
             j < c.first[k + PREFETCH_CLUSTERS] + c.count[k + PREFETCH_CLUSTERS]; j++)
          __builtin_prefetch(balls.at + (size_t)b->ids[j] * balls.stride);
      BvhNode root = cluster_node(b, balls, c.first[k], c.count[k], t.first[k]);
      t.boxes[k] = node_box(&root);
      t.first[k] = root.index;
      t.count[k] = root.meta;
      t.ids[k] = k;
    }
    group_clusters(&gr, &t, &g);
    SahBuild top = {.items = g.boxes, .ids = g.ids, .weight = g.weight, .nodes = b->nodes,
                    .leaf_max = 1, .leaf_node = g.leaf_node, .leaf_depth = g.leaf_depth};
#pragma omp parallel
#pragma omp single
    sah_build_node(&top, 0, 0, gr.n, 0, 1);
    SahBuild mid = {.items = t.boxes, .ids = t.ids, .weight = t.weight, .nodes = b->nodes,
                    .leaf_max = 1, .leaf_node = t.leaf_node};
#pragma omp parallel for schedule(dynamic, 16)
    for (int p = 0; p < gr.n; p++)
      sah_build_node(&mid, g.leaf_node[p], g.first[g.ids[p]], g.count[g.ids[p]],
                     g.leaf_depth[p], g.place[g.ids[p]]);
#pragma omp parallel for schedule(static)
    for (int p = 0; p < c.n; p++) /* each cluster's root at its leaf's slot */
      b->nodes[t.leaf_node[p]] = node_make(&t.boxes[p], t.first[t.ids[p]], t.count[t.ids[p]]);
  }
  free(c.first);
  free(c.count);
  free(gr.first);
  free(gr.count);
  top_free(&t);
  top_free(&g);
  *n_nodes = 2 * leaves - 1;
  return ok;
}

static int compare_int(const void *a, const void *b)
{
  int x = *(const int *)a, y = *(const int *)b;
  return (x > y) - (x < y);
}

bool bvh_build(Bvh *bvh, Balls balls, int n, int leaf_max)
{
  SahBuild b = {.leaf_max = leaf_max, .one_leaf = leaf_max >= n};
  b.ids = malloc((size_t)n * sizeof *b.ids);
  b.nodes = malloc((size_t)(2 * n - 1) * sizeof *b.nodes);
  *bvh = (Bvh){0};
  bool ok = b.ids && b.nodes;
  int n_nodes = 0;
  if (ok && n > CLUSTER_FROM && !b.one_leaf && leaf_max >= 2) {
    /* The node array (64 n bytes), written only once the clusters are cut,
     * holds the sort's pairs (16 n bytes) until then, so the nodes land on
     * pages already touched (fewer page faults); the clusters are cut from the
     * sorted pairs themselves. */
    uint64_t *scratch = (uint64_t *)(void *)b.nodes;
    ok = morton_sort(balls, n, b.ids, scratch) &&
         build_clustered(&b, balls, n, scratch + n, &n_nodes);
  } else if (ok && (b.items = malloc((size_t)n * sizeof *b.items))) {
    for (int k = 0; k < n; k++) { /* the heuristic moves its items: its own boxes */
      b.items[k] = ball_box(balls_get(balls, k));
      b.ids[k] = k;
    }
#pragma omp parallel if (n > 8192)
#pragma omp single
    sah_build_node(&b, 0, 0, n, 0, 1);
    free(b.items);
    ok = squeeze(&b.nodes, n, &n_nodes);
    for (int k = 0; ok && k < n_nodes; k++)
      if (b.nodes[k].meta > 1)
        qsort(b.ids + b.nodes[k].index, (size_t)b.nodes[k].meta, sizeof(int), compare_int);
  } else {
    ok = false; /* no room for the boxes */
  }
  if (!ok) {
    fprintf(stderr, "bvh: out of memory for %d spheres\n", n);
    free(b.nodes);
    free(b.ids);
    return false;
  }
  *bvh = (Bvh){.nodes = b.nodes, .n_nodes = n_nodes, .order = b.ids, .n_items = n};
  return true;
}
void bvh_free(Bvh *bvh)
{
  free(bvh->nodes);
  free(bvh->order);
  *bvh = (Bvh){0};
}
