/* Numbers of the scene format (step 02): the float strtof gives, and what
 * is wrong with a word that is not a plain finite float.
 * docs/scene-format.md, "Numbers". */
#include "app/number.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* What strtof says of the whole word, read from a terminated copy. */
NumberStatus number_parse(const char *s, int len, float *out)
{
  char small[128], *buf = len < (int)sizeof small ? small : malloc((size_t)len + 1);
  if (!buf)
    return NUMBER_BAD;
  memcpy(buf, s, (size_t)len);
  buf[len] = '\0';
  char *end;
  errno = 0;
  float v = strtof(buf, &end);
  bool whole = end == buf + len && len > 0, range = errno == ERANGE;
  if (buf != small)
    free(buf);
  if (!whole)
    return NUMBER_BAD;
  if (!isfinite(v))
    return NUMBER_NONFINITE;
  if ((v != 0.0f && fabsf(v) < FLT_MIN) || (v == 0.0f && range))
    return NUMBER_TINY;
  *out = v;
  return NUMBER_OK;
}
