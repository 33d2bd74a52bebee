/* Sampling patterns of step 07: names here, the patterns below.
 * docs/07-antialiasing.md. */
#include "sampler.h"

#include <string.h>

static const char *const NAMES[SAMPLER_COUNT] = {"center", "grid", "random",
                                                 "jitter", "sobol"};

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
