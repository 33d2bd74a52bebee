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

/* Parse a sampler name ("center", "grid", "random", "jitter", "sobol"). */
bool sampler_parse(const char *name, SamplerKind *out);

/* The name of a sampler kind. */
const char *sampler_name(SamplerKind kind);

#endif
