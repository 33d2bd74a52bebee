/* Morton order of box centres (common/accel/bvh.c's clusters): codes on a
 * cubic grid, a radix sort, runs of neighbours. docs/performance.md. */
#include "accel/morton.h"

#include <stdlib.h>
#include <string.h>

enum { MORTON_BITS = 10 }; /* per axis */

/* The 10 low bits of x spread to every third bit. */
static uint32_t spread3(uint32_t x)
{
  x = (x | x << 16) & 0x030000ffu;
  x = (x | x << 8) & 0x0300f00fu;
  x = (x | x << 4) & 0x030c30c3u;
  return (x | x << 2) & 0x09249249u;
}

/* Morton codes of the box centres, on a cubic grid over their bounds (a
 * flat scene is not cut along its thin axis). */
void morton_codes(const Box *items, int n, uint32_t *code)
{
  Box cb = sah_box_empty();
  float lo0 = cb.lo[0], lo1 = cb.lo[1], lo2 = cb.lo[2];
  float hi0 = cb.hi[0], hi1 = cb.hi[1], hi2 = cb.hi[2];
#pragma omp parallel for schedule(static) if (n > 65536) \
    reduction(min : lo0, lo1, lo2) reduction(max : hi0, hi1, hi2)
  for (int k = 0; k < n; k++) {
    V4 c = items[k].lo + items[k].hi;
    lo0 = c[0] < lo0 ? c[0] : lo0, hi0 = c[0] > hi0 ? c[0] : hi0;
    lo1 = c[1] < lo1 ? c[1] : lo1, hi1 = c[1] > hi1 ? c[1] : hi1;
    lo2 = c[2] < lo2 ? c[2] : lo2, hi2 = c[2] > hi2 ? c[2] : hi2;
  }
  cb.lo = (V4){lo0, lo1, lo2, 0.0f};
  cb.hi = (V4){hi0, hi1, hi2, 0.0f};
  float extent = 0.0f;
  for (int a = 0; a < 3; a++)
    extent = cb.hi[a] - cb.lo[a] > extent ? cb.hi[a] - cb.lo[a] : extent;
  float scale = extent > 0.0f ? (float)(1 << MORTON_BITS) / extent : 0.0f;
#pragma omp parallel for schedule(static) if (n > 65536)
  for (int k = 0; k < n; k++) {
    uint32_t q[3];
    for (int a = 0; a < 3; a++) { /* clamped before the conversion */
      float x = (items[k].lo[a] + items[k].hi[a] - cb.lo[a]) * scale;
      x = x > 0.0f ? x : 0.0f;
      q[a] = (uint32_t)(x < (float)((1 << MORTON_BITS) - 1) ? x : (1 << MORTON_BITS) - 1);
    }
    code[k] = spread3(q[0]) << 2 | spread3(q[1]) << 1 | spread3(q[2]);
  }
}

/* order[0 .. n) sorted by code, ties in index order: three 10-bit radix
 * passes over (code, index) pairs, read in sequence. */
bool morton_order(const uint32_t *code, int n, int *order)
{
  uint64_t *pair = malloc((size_t)n * sizeof *pair), *tmp = malloc((size_t)n * sizeof *tmp);
  if (!pair || !tmp) {
    free(pair);
    free(tmp);
    return false;
  }
  for (int k = 0; k < n; k++)
    pair[k] = (uint64_t)code[k] << 32 | (uint32_t)k;
  enum { BUCKETS = 1 << MORTON_BITS };
  for (int shift = 32; shift < 32 + 3 * MORTON_BITS; shift += MORTON_BITS) {
    int start[BUCKETS] = {0};
    for (int k = 0; k < n; k++)
      start[pair[k] >> shift & (BUCKETS - 1)]++;
    for (int b = 0, sum = 0; b < BUCKETS; b++) {
      int c = start[b];
      start[b] = sum;
      sum += c;
    }
    for (int k = 0; k < n; k++)
      tmp[start[pair[k] >> shift & (BUCKETS - 1)]++] = pair[k];
    uint64_t *swap = pair;
    pair = tmp;
    tmp = swap;
  }
  for (int k = 0; k < n; k++)
    order[k] = (int)(uint32_t)pair[k];
  free(pair);
  free(tmp);
  return true;
}

void morton_runs(const uint32_t *sorted, int first, int count, int max, MortonRuns *c)
{
  if (count <= max) {
    c->first[c->n] = first;
    c->count[c->n++] = count;
    return;
  }
  uint32_t diff = sorted[first] ^ sorted[first + count - 1];
  int mid = first + count / 2;
  if (diff != 0) {
    uint32_t bit = 1u << (31 - __builtin_clz(diff));
    int lo = first, hi = first + count - 1; /* first index with the bit set */
    while (lo < hi) {
      int m = lo + (hi - lo) / 2;
      if (sorted[m] & bit)
        hi = m;
      else
        lo = m + 1;
    }
    mid = lo;
  }
  morton_runs(sorted, first, mid - first, max, c);
  morton_runs(sorted, mid, first + count - mid, max, c);
}

/* Put the boxes in Morton order (items and ids alike); *codes: the sorted
 * codes (the caller frees them). */
bool morton_sort(SahBuild *b, int n, uint32_t **codes)
{
  uint32_t *code = malloc((size_t)n * sizeof *code);
  int *order = malloc((size_t)n * sizeof *order), *ids = malloc((size_t)n * sizeof *ids);
  Box *items = malloc((size_t)n * sizeof *items);
  bool ok = code && order && ids && items;
  if (ok) {
    morton_codes(b->items, n, code);
    ok = morton_order(code, n, order);
  }
#pragma omp parallel for schedule(static) if (ok && n > 65536)
  for (int k = 0; k < (ok ? n : 0); k++) {
    items[k] = b->items[order[k]];
    ids[k] = b->ids[order[k]];
    order[k] = (int)code[order[k]]; /* the codes in the new order */
  }
  if (ok) {
    memcpy(code, order, (size_t)n * sizeof *code);
    free(b->items);
    free(b->ids);
    b->items = items;
    b->ids = ids;
    *codes = code;
  } else {
    free(items);
    free(ids);
    free(code);
  }
  free(order);
  return ok;
}

