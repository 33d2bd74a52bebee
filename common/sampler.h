/* Where a pixel's samples go (step 07): centre, regular grid, uniform random,
 * jittered (stratified) and a scrambled low-discrepancy sequence, all keyed by
 * pixel and sample index. docs/07-antialiasing.md. */
#ifndef RT_SAMPLER_H
#define RT_SAMPLER_H

#include <stdbool.h>
#include <stdint.h>
#include "vec.h"

typedef enum SamplerKind {
  SAMPLER_CENTER, /* every sample at the pixel centre (the lecture's GetSample) */
  SAMPLER_GRID,   /* regular k x k grid of cell centres */
  SAMPLER_RANDOM, /* independent uniform points */
  SAMPLER_JITTER, /* one uniform point in each cell of a k x k grid */
  SAMPLER_SOBOL,  /* Sobol (0,2) sequence, scrambled per pixel */
  SAMPLER_COUNT
} SamplerKind;

/* How a render places its samples (steps 07, 08): the pattern of a pixel's
 * camera samples and of an area light's light samples, the seed that keys
 * them, and the threshold of adaptive sampling (0: off). The command line
 * sets it (--sampler, --seed, --adaptive). */
typedef struct Sampler {
  SamplerKind kind;
  uint32_t seed;
  float adaptive;
} Sampler;

/* Parse a sampler name ("center", "grid", "random", "jitter", "sobol"). */
bool sampler_parse(const char *name, SamplerKind *out);

/* The name of a sampler kind. */
const char *sampler_name(SamplerKind kind);

/* The samples 0 .. count - 1 of one pixel (j * width + i) for one seed: what
 * sampler_point needs, computed once (the Sobol scramble of the pixel). */
typedef struct SamplerPattern {
  SamplerKind kind;
  uint32_t seed, pixel, count;
  uint32_t scramble[2]; /* Sobol: the pixel's scramble seeds, x and y */
} SamplerPattern;

/* The pattern of `count` samples of pixel `pixel` for `seed`. */
SamplerPattern sampler_pattern(SamplerKind kind, uint32_t seed, uint32_t pixel,
                               uint32_t count);

/* The pattern of `count` samples for the point p in stream `stream` (step
 * 08: an area light's index), keyed by `seed`, the stream and p's
 * coordinates (their bits): each point draws a pattern of its own, the same
 * whichever thread asks. */
SamplerPattern sampler_pattern_at(SamplerKind kind, uint32_t seed, uint32_t stream, vec3s p,
                                  uint32_t count);

/* Sample `index` of the pattern: a point of [0,1)^2 inside the pixel, (0,0)
 * its bottom-left corner. Grid and jitter spread the `count` samples over
 * `count` cells of equal area 1/count (a k x k grid when count is a square;
 * otherwise r = floor(sqrt(count)) rows, row q holding
 * floor((q+1) count/r) - floor(q count/r) cells and as tall as that count
 * over `count`). Sobol and random ignore `count`: any run of samples from 0
 * is already spread over the pixel (the Sobol points 0..2^m-1 hold one point
 * in every elementary box of area 2^-m). Random numbers come from
 * rng_make(seed, pixel, index) only. Requires index < count. */
vec2s sampler_point(const SamplerPattern *pattern, uint32_t index);

/* sampler_point(&sampler_pattern(kind, seed, pixel, count), index). */
vec2s sampler_get(SamplerKind kind, uint32_t seed, uint32_t pixel, uint32_t index,
                  uint32_t count);

#endif
