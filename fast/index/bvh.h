/* Bounding volume hierarchy over the spheres' cubes, built top-down with the
 * binned surface area heuristic: the build half of the scene's acceleration
 * structure (fast/index/accel.c traverses it). docs/performance.md. */
#ifndef RT_BVH_H
#define RT_BVH_H

#include <stdbool.h>

#include "index/box.h"

typedef struct Bvh {
  BvhNode *nodes; /* nodes[0] is the root; owned */
  int n_nodes;
  int *order;     /* item indices in leaf order; owned */
  int n_items;
} Bvh;

/* Build over the cubes of n >= 1 balls, leaves of at most leaf_max items
 * (leaf_max >= n: the root is one leaf of all of them). Deterministic (same
 * input, same tree, for any number of threads). False (one line printed)
 * when out of memory; bvh is then empty. */
bool bvh_build(Bvh *bvh, Balls balls, int n, int leaf_max);

/* Free the tree; a second call is harmless. */
void bvh_free(Bvh *bvh);

#endif
