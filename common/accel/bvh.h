/* Bounding volume hierarchy over boxes, built top-down with the binned surface
 * area heuristic: the build half of the scene's acceleration structure
 * (common/accel/accel.c traverses it). docs/performance.md. */
#ifndef RT_BVH_H
#define RT_BVH_H

#include <stdbool.h>

/* One node, 32 bytes. Inner node: children nodes[index] and nodes[index + 1],
 * meta = -1 - split axis. Leaf: items order[index .. index + meta), meta > 0. */
typedef struct BvhNode {
  float lo[3], hi[3]; /* bounds of everything below */
  int index;
  int meta;
} BvhNode;

typedef struct Bvh {
  BvhNode *nodes; /* nodes[0] is the root; owned */
  int n_nodes;
  int *order;     /* item indices in leaf order; owned */
  int n_items;
} Bvh;

/* Build over n >= 1 boxes lo[k]..hi[k], leaves of at most leaf_max items
 * (leaf_max >= n: the root is one leaf of all of them).
 * Deterministic (same input, same tree). False (one line printed) when out of
 * memory; bvh is then empty. */
bool bvh_build(Bvh *bvh, const float (*lo)[3], const float (*hi)[3], int n,
               int leaf_max);

/* Free the tree; a second call is harmless. */
void bvh_free(Bvh *bvh);

#endif
