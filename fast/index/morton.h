/* Morton order: ball centres interleaved bit by bit into one code (10 bits an
 * axis), so that sorting by code puts neighbours in space next to each
 * other. The BVH build's clusters (fast/index/bvh.c); docs/performance.md. */
#ifndef RT_MORTON_H
#define RT_MORTON_H

#include <stdbool.h>
#include <stdint.h>

#include "index/box.h"

/* ids[0 .. n): the balls' indices sorted by the Morton code of their
 * centres (on a cubic grid over the centres' bounds, so that a flat scene is
 * not cut along its thin axis), ties in index order. scratch: room for 2n
 * pairs (code << 32 | index), which the radix sort uses; it leaves the
 * sorted pairs in scratch[n .. 2n) (scratch must not overlap ids). The same
 * for any number of threads. False when out of memory. */
bool morton_sort(Balls items, int n, int *ids, uint64_t *scratch);

/* Runs of the sorted codes, each of at most `max` balls. */
typedef struct MortonRuns {
  int *first, *count; /* ranges of the sorted balls */
  int n;
} MortonRuns;

/* Cut the sorted pairs [first, first + count) (morton_sort's) at their
 * codes' highest differing bit until each part holds at most `max` balls
 * (equal codes: by count), appending the parts to r. */
void morton_runs(const uint64_t *sorted, int first, int count, int max, MortonRuns *r);

#endif
