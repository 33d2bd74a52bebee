/* Numbers of the scene format: a word to the float C's strtof rounds it to.
 * Introduced in step 02; docs/scene-format.md, "Numbers". */
#ifndef RT_NUMBER_H
#define RT_NUMBER_H

typedef enum NumberStatus {
  NUMBER_OK,        /* a finite float: zero or at least FLT_MIN in magnitude */
  NUMBER_BAD,       /* not a number strtof reads completely */
  NUMBER_NONFINITE, /* inf, nan, or too large for a float (1e39) */
  NUMBER_TINY,      /* not zero, but below FLT_MIN in magnitude (1e-40) */
} NumberStatus;

/* Read the `len` bytes at `s` (no terminator needed) as strtof would read the
 * same text: *out is bit for bit strtof's result whenever NUMBER_OK. */
NumberStatus number_parse(const char *s, int len, float *out);

#endif
