/* Counter-based random numbers keyed by (seed, pixel, sample), never by
 * thread or time: a render is the same bytes on any thread count (step 07,
 * docs/07-antialiasing.md). */
#ifndef RT_RNG_H
#define RT_RNG_H

#include <stdint.h>

typedef struct Rng {
  uint64_t state;
} Rng;

/* 64-bit finalizer (splitmix64's): a bijection that mixes every input bit. */
static inline uint64_t rng_mix(uint64_t x)
{
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

/* The stream of pixel `pixel` (j * width + i), sample `sample`, for `seed`. */
static inline Rng rng_make(uint32_t seed, uint32_t pixel, uint32_t sample)
{
  Rng r = {rng_mix(((uint64_t)seed << 32 | pixel) ^ rng_mix(sample + 0x9e3779b97f4a7c15ull))};
  return r;
}

/* Next 32 random bits (splitmix64 step). */
static inline uint32_t rng_next(Rng *r)
{
  r->state += 0x9e3779b97f4a7c15ull;
  return (uint32_t)(rng_mix(r->state) >> 32);
}

/* Uniform float in [0, 1): 24 random bits times 2^-24, so never 1.0f. */
static inline float rng_float(Rng *r)
{
  return (float)(rng_next(r) >> 8) * 0x1p-24f;
}

#endif
