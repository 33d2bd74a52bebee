/* Sampling patterns of step 07: where sample k of a pixel lies, as a function
 * of (seed, pixel, k) alone. docs/07-antialiasing.md explains each pattern. */
#include "sampler.h"

#include <math.h>
#include <string.h>

#include "rng.h"

static const char *const NAMES[SAMPLER_COUNT] = {"center", "grid", "random",
                                                 "jitter", "sobol"};

/* The largest float below 1: a coordinate that rounds up to 1 is put here. */
static const float BELOW_ONE = 0x1.fffffep-1f;

bool sampler_parse(const char *name, SamplerKind *out)
{
  for (int k = 0; k < SAMPLER_COUNT; k++) {
    if (strcmp(name, NAMES[k]) == 0) {
      *out = (SamplerKind)k;
      return true;
    }
  }
  return false;
}

const char *sampler_name(SamplerKind kind)
{
  return kind < SAMPLER_COUNT ? NAMES[kind] : "?";
}

/* The camera sample's random numbers: the stream of (seed, pixel, index)
 * jumped 2^32 draws ahead, so shading may draw from the start of the same
 * stream (step 08's light samples) without repeating these numbers. */
static Rng sample_rng(uint32_t seed, uint32_t pixel, uint32_t index)
{
  Rng r = rng_make(seed, pixel, index);
  r.state += 0x9e3779b97f4a7c15ull << 32;
  return r;
}

/* Point (u, v) of [0,1)^2 placed in cell `cell` of `count` equal-area cells:
 * rows = floor(sqrt(count)); row q holds cells [start(q), start(q+1)) with
 * start(q) = floor(q count / rows), and is (start(q+1) - start(q)) / count tall,
 * so every cell has area 1/count and count = k^2 gives the k x k grid. */
static vec2s cell_point(uint32_t cell, uint32_t count, float u, float v)
{
  /* rows = floor(sqrt(count)), at least 1. The double square root is already
   * exact enough for any 32-bit count; the loops only guarantee it. */
  uint64_t rows = (uint64_t)sqrt((double)count);
  while (rows * rows > count)
    rows--;
  while ((rows + 1) * (rows + 1) <= count)
    rows++;
  rows = rows > 0 ? rows : 1;
  uint64_t q, start, cols;
  if (rows * rows == count) { /* the k x k grid: the same q, start and cols */
    q = (uint32_t)cell / (uint32_t)rows;
    start = q * rows;
    cols = rows;
  } else { /* the largest q with start(q) <= cell: q count < (cell + 1) rows */
    q = ((cell + 1) * rows - 1) / count;
    start = q * count / rows;
    cols = (q + 1) * count / rows - start;
  }
  float x = ((float)(cell - start) + u) / (float)cols;
  float y = ((float)start + v * (float)cols) / (float)count;
  /* fminf(x, BELOW_ONE) written out: the same value, without a libm call. */
  vec2s s = {.x = x < BELOW_ONE ? x : BELOW_ONE, .y = y < BELOW_ONE ? y : BELOW_ONE};
  return s;
}

/* The grid's points are the same for every pixel: each thread keeps tables
 * of the values cell_point gives for the last two counts (camera and light
 * samples), each computed once. */
enum { GRID_CACHE_MAX = 4096 };

static vec2s grid_point(uint32_t cell, uint32_t count)
{
  static _Thread_local uint32_t cached[2], older;
  static _Thread_local vec2s table[2][GRID_CACHE_MAX];
  if (count > GRID_CACHE_MAX || cell >= count)
    return cell_point(cell, count, 0.5f, 0.5f);
  int slot = cached[0] == count ? 0 : cached[1] == count ? 1 : -1;
  if (slot < 0) {
    slot = (int)older;
    older ^= 1u;
    for (uint32_t k = 0; k < count; k++)
      table[slot][k] = cell_point(k, count, 0.5f, 0.5f);
    cached[slot] = count;
  }
  return table[slot][cell];
}

static uint32_t reverse_bits(uint32_t x)
{
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
  return x;
}

/* Second Sobol dimension as 32 fixed-point bits: the generator matrix has
 * columns v_k = v_{k-1} ^ (v_{k-1} >> 1), v_0 = 2^31 (Pascal's triangle mod 2).
 * The first dimension is the van der Corput sequence, reverse_bits(i). */
static uint32_t sobol_dim2(uint32_t i)
{
  uint32_t r = 0;
  for (uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
    if (i & 1)
      r ^= v;
  return r;
}

/* Nested uniform (Owen) scramble of a 32-bit fraction, hash-based (Burley
 * 2020, "Practical Hash-based Owen Scrambling", with Vegdahl's constants).
 * On the reversed bits, the hash changes each bit only as a function of the
 * bits below it: so each digit of x is flipped as a random function of the
 * digits above it, which is Owen's scramble, and boxes of the net map to boxes. */
static uint32_t owen_scramble(uint32_t x, uint32_t seed)
{
  x = reverse_bits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverse_bits(x);
}

/* 32 fixed-point bits to a float in [0,1): the top 24 bits times 2^-24. */
static float fraction(uint32_t x)
{
  return (float)(x >> 8) * 0x1p-24f;
}

SamplerPattern sampler_pattern(SamplerKind kind, uint32_t seed, uint32_t pixel,
                               uint32_t count)
{
  SamplerPattern p = {.kind = kind, .seed = seed, .pixel = pixel, .count = count};
  if (kind == SAMPLER_SOBOL) {
    /* One pair of scramble seeds per pixel: the stream of sample 2^32 - 1,
     * an index no pixel reaches (at most SCENE_MAX_SAMPLES samples). */
    Rng px = sample_rng(seed, pixel, UINT32_MAX);
    p.scramble[0] = rng_next(&px);
    p.scramble[1] = rng_next(&px);
  }
  return p;
}

SamplerPattern sampler_pattern_at(SamplerKind kind, uint32_t seed, uint32_t stream, vec3s p,
                                  uint32_t count)
{
  uint32_t b[3];
  memcpy(b, &p, sizeof b);
  Rng r = rng_make(seed ^ (0x9e3779b9u * (stream + 1u)), b[0] ^ (b[2] * 0x85ebca77u), b[1]);
  /* Two draws in a fixed order (C leaves the order of a call's arguments
   * unspecified). */
  uint32_t pixel = rng_next(&r);
  uint32_t pattern_seed = rng_next(&r);
  return sampler_pattern(kind, pattern_seed, pixel, count);
}

vec2s sampler_point(const SamplerPattern *p, uint32_t index)
{
  vec2s s = {.x = 0.5f, .y = 0.5f};
  switch (p->kind) {
  case SAMPLER_GRID:
    return grid_point(index, p->count);
  case SAMPLER_RANDOM: {
    Rng r = sample_rng(p->seed, p->pixel, index);
    s.x = rng_float(&r);
    s.y = rng_float(&r);
    return s;
  }
  case SAMPLER_JITTER: {
    Rng r = sample_rng(p->seed, p->pixel, index);
    float u = rng_float(&r);
    return cell_point(index, p->count, u, rng_float(&r));
  }
  case SAMPLER_SOBOL:
    s.x = fraction(owen_scramble(reverse_bits(index), p->scramble[0]));
    s.y = fraction(owen_scramble(sobol_dim2(index), p->scramble[1]));
    return s;
  case SAMPLER_CENTER:
  case SAMPLER_COUNT:
    break;
  }
  return s;
}

vec2s sampler_get(SamplerKind kind, uint32_t seed, uint32_t pixel, uint32_t index,
                  uint32_t count)
{
  SamplerPattern p = sampler_pattern(kind, seed, pixel, count);
  return sampler_point(&p, index);
}
