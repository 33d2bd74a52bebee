/* Numbers of the scene format: a word to the float C's strtof rounds it to,
 * with a fast exact path for plain decimals (a scene of 10^6 spheres holds
 * 4 x 10^6 of them). Introduced in step 02; docs/scene-format.md, "Numbers". */
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

/* The plain decimal at s (read at most to end), when number_parse would read
 * it without strtof: returns where it stops (the first byte that does not
 * continue it), with *out the float number_parse gives for the bytes before
 * that; NULL otherwise (no decimal there, or one number_parse hands to
 * strtof). For the parser's fast path (common/app/parser_state.c, sphere_line). */
const char *number_prefix(const char *s, const char *end, float *out);

#endif
