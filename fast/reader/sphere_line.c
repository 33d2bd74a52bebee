/* The line a large scene is made of, read straight from the text
 * (reader/sphere_line.h). */
#include "reader/sphere_line.h"

#include <string.h>

#include "reader/decimal.h"

bool sphere_line_on = true;

/* The word at s is `word` followed by one space. */
static bool word_then_space(const char *s, const char *end, const char *word, size_t len)
{
  return (size_t)(end - s) > len && memcmp(s, word, len) == 0 && s[len] == ' ';
}

/* The plain decimal at s then one space: the byte after that space, NULL
 * otherwise; *longest grows to the decimal's length. Inlined into each of
 * sphere_line_read's four reads, decimal_prefix's short path with it (gcc
 * left it a call). */
__attribute__((always_inline)) static inline const char *number_then_space(const char *s,
                                                                          const char *end,
                                                                          float *v,
                                                                          int *longest)
{
  const char *stop = decimal_prefix(s, end, v);
  if (!stop || stop >= end || *stop != ' ')
    return NULL;
  *longest = stop - s > *longest ? (int)(stop - s) : *longest;
  return stop + 1;
}

bool sphere_line_read(const char *line, const char *end, PackSphereLine *out)
{
  const char *s = line;
  int longest = 0;
  if (!sphere_line_on || !word_then_space(s, end, "sphere", 6) ||
      !word_then_space(s + 7, end, "center", 6))
    return false;
  s += 14;
  for (int k = 0; k < 3; k++)
    if (!(s = number_then_space(s, end, &out->v[k], &longest)))
      return false;
  if (!word_then_space(s, end, "radius", 6) ||
      !(s = number_then_space(s + 7, end, &out->v[3], &longest)) ||
      !word_then_space(s, end, "material", 8))
    return false;
  s += 9;
  const char *name = s, *nl = memchr(s, '\n', (size_t)(end - s));
  const char *stop = nl ? nl : end;
  if (stop == name || memchr(name, ' ', (size_t)(stop - name)))
    return false;
  out->name = name;
  out->name_len = (int)(stop - name);
  out->longest = longest > out->name_len ? longest : out->name_len;
  out->next = nl ? nl + 1 : end;
  return true;
}
