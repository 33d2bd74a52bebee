/* Morton order of ball centres (fast/index/bvh.c's clusters): codes on a
 * cubic grid, a radix sort, runs of neighbours. docs/performance.md. */
#include "index/morton.h"

#include "threads.h"
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

/* (code << 32 | k) for each ball k: its centre's Morton code on a cubic grid
 * over the centres' bounds (a flat scene is not cut along its thin axis). */
static void morton_codes(Balls items, int n, uint64_t *pair)
{
  Box4 cb = box4_empty();
  float lo0 = cb.lo[0], lo1 = cb.lo[1], lo2 = cb.lo[2];
  float hi0 = cb.hi[0], hi1 = cb.hi[1], hi2 = cb.hi[2];
#pragma omp parallel for schedule(static) if (n > 65536) \
    reduction(min : lo0, lo1, lo2) reduction(max : hi0, hi1, hi2)
  for (int k = 0; k < n; k++) {
    V4 c = balls_get(items, k);
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
  /* Each axis's cell spread by a table (4 KB), the clamps done on the three
   * lanes at once: cheaper than the spreads' shifts and branches. */
  uint32_t spread[1 << MORTON_BITS];
  for (uint32_t x = 0; x < (1u << MORTON_BITS); x++)
    spread[x] = spread3(x);
  V4 lo = cb.lo, step = {scale, scale, scale, 0.0f}, zero = {0.0f, 0.0f, 0.0f, 0.0f};
  V4 top = {(float)((1 << MORTON_BITS) - 1), (float)((1 << MORTON_BITS) - 1),
            (float)((1 << MORTON_BITS) - 1), 0.0f};
#pragma omp parallel for schedule(static) if (n > 65536)
  for (int k = 0; k < n; k++) {
    V4 x = (balls_get(items, k) - lo) * step;
    I4 above = x > zero, below = x < top; /* clamped before the conversion */
    x = (V4)((I4)x & above);
    x = (V4)(((I4)x & below) | ((I4)top & ~below));
    uint32_t code = spread[(int)x[0]] << 2 | spread[(int)x[1]] << 1 | spread[(int)x[2]];
    pair[k] = (uint64_t)code << 32 | (uint32_t)k;
  }
}

enum { BUCKETS = 1 << MORTON_BITS };

/* One stable counting pass on the 10 bits at `shift`, from `in` to `out`:
 * each of the team's threads counts, then moves, one block of the pairs;
 * bucket by bucket, block t's pairs go after those of the blocks before it,
 * so the result is the same for any number of threads. `count` holds
 * BUCKETS ints a thread. Call it from every thread of a parallel region. */
static void radix_pass(const uint64_t *in, uint64_t *out, int n, int shift, int *count)
{
  int threads = omp_get_num_threads(), t = omp_get_thread_num();
  int first = (int)((long long)n * t / threads), last = (int)((long long)n * (t + 1) / threads);
  int *mine = count + (size_t)t * BUCKETS;
  memset(mine, 0, BUCKETS * sizeof *mine);
  for (int k = first; k < last; k++)
    mine[in[k] >> shift & (BUCKETS - 1)]++;
#pragma omp barrier
#pragma omp single
  for (int b = 0, sum = 0; b < BUCKETS; b++)
    for (int u = 0; u < threads; u++) {
      int c = count[(size_t)u * BUCKETS + b];
      count[(size_t)u * BUCKETS + b] = sum;
      sum += c;
    }
  for (int k = first; k < last; k++)
    out[mine[in[k] >> shift & (BUCKETS - 1)]++] = in[k];
#pragma omp barrier
}

/* The pairs sorted by code, ties in index order (the index is the low half):
 * three radix passes of 10 bits over the code half, from pair[0 .. n) to
 * pair[n .. 2n) and back; the result in pair[n .. 2n). */
static bool sort_pairs(uint64_t *pair, int n)
{
  int threads = n > 65536 ? omp_get_max_threads() : 1;
  int *count = malloc((size_t)threads * BUCKETS * sizeof *count);
  if (!count)
    return false;
#pragma omp parallel num_threads(threads)
  {
    const uint64_t *in = pair;
    uint64_t *out = pair + n;
    for (int shift = 32; shift < 32 + 3 * MORTON_BITS; shift += MORTON_BITS) {
      radix_pass(in, out, n, shift, count);
      const uint64_t *done = out;
      out = (uint64_t *)in;
      in = done;
    }
  }
  free(count);
  return true;
}

void morton_runs(const uint64_t *sorted, int first, int count, int max, MortonRuns *c)
{
  if (count <= max) {
    c->first[c->n] = first;
    c->count[c->n++] = count;
    return;
  }
  uint32_t diff = (uint32_t)((sorted[first] ^ sorted[first + count - 1]) >> 32);
  int mid = first + count / 2;
  if (diff != 0) {
    uint32_t bit = 1u << (31 - __builtin_clz(diff));
    int lo = first, hi = first + count - 1; /* first index with the bit set */
    while (lo < hi) {
      int m = lo + (hi - lo) / 2;
      if (sorted[m] >> 32 & bit)
        hi = m;
      else
        lo = m + 1;
    }
    mid = lo;
  }
  morton_runs(sorted, first, mid - first, max, c);
  morton_runs(sorted, mid, first + count - mid, max, c);
}

bool morton_sort(Balls items, int n, int *ids, uint64_t *scratch)
{
  morton_codes(items, n, scratch);
  if (!sort_pairs(scratch, n))
    return false;
  const uint64_t *sorted = scratch + n;
#pragma omp parallel for schedule(static) if (n > 65536)
  for (int k = 0; k < n; k++)
    ids[k] = (int)(uint32_t)sorted[k];
  return true;
}
