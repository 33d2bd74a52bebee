/* Boxes and balls of the BVH build (index/bvh.c, index/bvh_sah.c,
 * index/morton.c): a shape's box (common/box.h's Box) in four float lanes,
 * so that growing one takes a few vector instructions, and the tree's node. */
#ifndef RT_INDEX_BOX_H
#define RT_INDEX_BOX_H

#include <float.h>
#include <stddef.h>
#include <string.h>

#include "scene.h"
#include "scene_index.h" /* Box, scene_instance_bounds, Instance */
#include "index/cones.h"

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
typedef struct Box4 {
  V4 lo, hi;
} Box4;

/* A shape's box (NAME_bounds, scene_instance_bounds) in lanes. */
static inline Box4 box4_of(Box b)
{
  return (Box4){{b.min.x, b.min.y, b.min.z, 0.0f}, {b.max.x, b.max.y, b.max.z, 0.0f}};
}

/* An item as the build receives it, 16 bytes where a Box4 takes 32: a
 * sphere as the scene stores it (struct Sphere), its centre in lanes 0 to 2
 * and its radius in lane 3. */
typedef V4 Ball;

/* The cube a ball stands for: the sphere's radius padded by the margin of
 * every culling test (sphere_pad, index/cones.h). */
static inline Box4 ball_box(Ball b)
{
  Sphere s = {.center = {{b[0], b[1], b[2]}}, .radius = b[3]};
  float h = b[3] + sphere_pad(&s);
  V4 c = {b[0], b[1], b[2], 0.0f}, e = {h, h, h, 0.0f};
  return (Box4){c - e, c + e};
}

/* Where a build reads its balls: ball k is the 16 bytes at at + k * stride
 * (16-byte aligned), so that the spheres of a scene's instances are read
 * where they are (stride sizeof(Instance)) instead of being copied first. */
typedef struct Balls {
  const char *at;
  size_t stride;
} Balls;

static inline Ball balls_get(Balls b, int k)
{
  Ball v;
  memcpy(&v, b.at + (size_t)k * b.stride, sizeof v);
  return v;
}

/* A node with bounds `box`, and a node's bounds as a box. */
static inline BvhNode node_make(const Box4 *box, int index, int meta)
{
  return (BvhNode){{box->lo[0], box->lo[1], box->lo[2]}, {box->hi[0], box->hi[1], box->hi[2]},
                   index, meta};
}

static inline Box4 node_box(const BvhNode *nd)
{
  return (Box4){{nd->lo[0], nd->lo[1], nd->lo[2], 0.0f}, {nd->hi[0], nd->hi[1], nd->hi[2], 0.0f}};
}

/* The empty box (lo > hi), and a box grown to hold x. */
static inline Box4 box4_empty(void)
{
  return (Box4){{FLT_MAX, FLT_MAX, FLT_MAX, 0.0f}, {-FLT_MAX, -FLT_MAX, -FLT_MAX, 0.0f}};
}

/* Lane by lane, a < b ? a : b. */
static inline V4 v4_min(V4 a, V4 b)
{
  I4 m = a < b;
  return (V4)((m & (I4)a) | (~m & (I4)b));
}

static inline V4 v4_max(V4 a, V4 b)
{
  I4 m = a > b;
  return (V4)((m & (I4)a) | (~m & (I4)b));
}

static inline void box4_grow(Box4 *b, const Box4 *x)
{
  b->lo = v4_min(x->lo, b->lo);
  b->hi = v4_max(x->hi, b->hi);
}

#endif
