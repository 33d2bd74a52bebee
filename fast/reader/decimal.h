/* Plain decimals (-3.95543, 0.00123456, 12e3) read without strtof, as
 * strtof rounds them: the large scene's sphere lines hold millions
 * (reader/sphere_line.c). */
#ifndef RT_DECIMAL_H
#define RT_DECIMAL_H

/* The plain decimal at s (read at most to end), when it can be read without
 * strtof: returns where it stops (the first byte that does not continue
 * it), with *out the float number_parse (app/number.h) gives for the bytes
 * before that; NULL otherwise (no decimal there, or one that needs
 * strtof). */
const char *decimal_prefix(const char *s, const char *end, float *out);

#endif
