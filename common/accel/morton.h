/* Morton order: box centres interleaved bit by bit into one code (10 bits an
 * axis), so that sorting by code puts neighbours in space next to each
 * other. The BVH build's clusters (common/accel/bvh.c); docs/performance.md. */
#ifndef RT_MORTON_H
#define RT_MORTON_H

#include <stdbool.h>
#include <stdint.h>

#include "accel/bvh_sah.h"

/* Codes of the n boxes' centres, on a cubic grid over their bounds (a flat
 * scene is not cut along its thin axis). */
void morton_codes(const Box *items, int n, uint32_t *code);

/* order[0 .. n) sorted by code, ties in index order. False when out of
 * memory. */
bool morton_order(const uint32_t *code, int n, int *order);

/* b's boxes (and ids) in Morton order; *codes the sorted codes, a new array
 * the caller frees. False when out of memory (b unchanged). */
bool morton_sort(SahBuild *b, int n, uint32_t **codes);

/* Runs of the sorted codes, each of at most `max` boxes. */
typedef struct MortonRuns {
  int *first, *count; /* ranges of the sorted boxes */
  int n;
} MortonRuns;

/* Cut sorted codes [first, first + count) at their highest differing bit
 * until each part holds at most `max` boxes (equal codes: by count),
 * appending the parts to r. */
void morton_runs(const uint32_t *sorted, int first, int count, int max, MortonRuns *r);

#endif
