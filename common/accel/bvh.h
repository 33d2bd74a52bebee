/* Bounding volume hierarchy over the spheres' cubes, built top-down with the
 * binned surface area heuristic: the build half of the scene's acceleration
 * structure (common/accel/accel.c traverses it). docs/performance.md. */
#ifndef RT_BVH_H
#define RT_BVH_H

#include <stdbool.h>

/* One node, 32 bytes. Inner node: children nodes[index] and nodes[index + 1],
 * meta = -1 - the axis they were split along, nodes[index] the lower of the
 * two along it (the closest-hit traversal visits the nearer first). Leaf:
 * items order[index .. index + meta), meta > 0, in increasing order. */
typedef struct BvhNode {
  float lo[3], hi[3]; /* bounds of everything below */
  int index;
  int meta;
} BvhNode;

/* An item's bounds in 4 lanes (the 4th stays 0), as GCC/clang vectors: a box
 * grows in a few vector instructions. */
typedef float V4 __attribute__((vector_size(16)));
typedef int I4 __attribute__((vector_size(16)));
typedef struct Box {
  V4 lo, hi;
} Box;

/* An item as the build receives it, 16 bytes where a Box takes 32: the
 * centre in lanes 0 to 2, in lane 3 the half width of the cube around it
 * (a sphere's radius and padding). */
typedef V4 Ball;

/* The cube a ball stands for. */
static inline Box ball_box(Ball b)
{
  V4 c = {b[0], b[1], b[2], 0.0f}, e = {b[3], b[3], b[3], 0.0f};
  return (Box){c - e, c + e};
}

/* A node with bounds `box`, and a node's bounds as a box. */
static inline BvhNode node_make(const Box *box, int index, int meta)
{
  return (BvhNode){{box->lo[0], box->lo[1], box->lo[2]}, {box->hi[0], box->hi[1], box->hi[2]},
                   index, meta};
}

static inline Box node_box(const BvhNode *nd)
{
  return (Box){{nd->lo[0], nd->lo[1], nd->lo[2], 0.0f}, {nd->hi[0], nd->hi[1], nd->hi[2], 0.0f}};
}

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
bool bvh_build(Bvh *bvh, const Ball *balls, int n, int leaf_max);

/* Free the tree; a second call is harmless. */
void bvh_free(Bvh *bvh);

#endif
