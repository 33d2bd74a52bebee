/* The binned surface-area-heuristic split of fast/index/bvh.c: the build of
 * a subtree over weighted boxes (docs/performance.md). Internal to
 * fast/index/bvh.c. */
#ifndef RT_BVH_SAH_H
#define RT_BVH_SAH_H

#include <stdbool.h>

#include "index/box.h"

/* A build over items (boxes), partitioned in place. With `weight`, item k
 * stands for weight[k] boxes (a cluster, or a group of clusters) and counts
 * that much in the heuristic; each leaf is then one item, whose slot
 * leaf_node[position] the caller fills (its subtree is kept elsewhere). */
typedef struct SahBuild {
  Box4 *items;
  int *ids;            /* moved with the items */
  int *weight;         /* NULL: 1 each */
  BvhNode *nodes;      /* a subtree of c items owns 2 c - 1 slots */
  int leaf_max;        /* most items a leaf may hold (1 with weights) */
  bool one_leaf;       /* the root is a leaf of everything */
  int *leaf_node;      /* with weights */
  int *leaf_depth;     /* with weights, or NULL: each leaf's depth */
} SahBuild;

/* The axis along which the middles of boxes a and b lie furthest apart;
 * *b_lower: b's middle is the lower along it. Two children split without
 * the heuristic go lower first by that axis (bvh.h). */
int sah_apart_axis(const Box4 *a, const Box4 *b, bool *b_lower);

/* Build node `node` over items [first, first + count) at `depth`; its
 * descendants go to the slots from `block` on (the left child's c_l items in
 * the 2 c_l - 2 after the pair, the right child's after them). Subtrees of
 * more than a few thousand items become OpenMP tasks: call it inside a
 * parallel region's single construct. The nodes are the same for any
 * number of threads. */
void sah_build_node(SahBuild *b, int node, int first, int count, int depth, int block);

#endif
