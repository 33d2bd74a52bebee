/* The names a scene file defines (materials), found in constant time on
 * average: an open-addressing hash table of indices into the caller's array
 * of records, each record starting with its NUL-terminated name. Introduced
 * in step 02 (the parser); docs/scene-format.md. */
#ifndef RT_NAMES_H
#define RT_NAMES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct Names {
  int32_t *slot;   /* record index, -1 for an empty slot */
  uint64_t *key;   /* the name in each slot as a number (names.c) */
  size_t cap;      /* a power of two, or 0 */
  size_t count;
} Names;

/* Where the records are: the name of record k is the string at
 * base + k * stride. The array may move between calls (pass it again). */
typedef struct NameRecords {
  const char *base;
  size_t stride;
} NameRecords;

void names_init(Names *t);
void names_free(Names *t);

/* The record called `name` (`len` bytes, not terminated), or -1. */
int names_find(const Names *t, NameRecords rec, const char *name, int len);

/* Record `index` now carries its name in `rec`: add it. False (one line
 * printed) when out of memory. The name must not be in the table yet. */
bool names_add(Names *t, NameRecords rec, int index);

#endif
