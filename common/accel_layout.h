/* The memory layout shared by the acceleration structure's queries
 * (accel.c) and its construction (accel_build.c); private to those two.
 * docs/performance.md. */
#ifndef RT_ACCEL_LAYOUT_H
#define RT_ACCEL_LAYOUT_H

#include "accel.h"
#include "bvh.h"

enum { LANES = 8 };

/* Up to LANES spheres; an unused lane has a NaN centre, which every
 * comparison of the kernel rejects, and instance index INT_MAX. */
typedef struct SphereBlock {
  _Alignas(32) float cx[LANES];
  _Alignas(32) float cy[LANES];
  _Alignas(32) float cz[LANES];
  _Alignas(32) float rad[LANES];
  int inst[LANES];
  vec3s bound_c;  /* flat layout: a sphere around the block's spheres, */
  float bound_r2; /* centre and squared radius (block_near) */
} SphereBlock;

struct SceneAccel {
  SphereBlock *blocks; /* leaf order of the hierarchy, or instance order */
  int n_blocks;
  BvhNode *nodes;      /* NULL: test every block; else leaf index = block */
  int *others;         /* instances not in blocks, lit ones first */
  int n_others, n_others_lit;
};

#endif
