/* Material names of a scene file in a hash table (step 02): FNV-1a hashes,
 * linear probing, the table at most half full. docs/scene-format.md. */
#include "app/names.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t hash_of(const char *s, int len)
{
  uint32_t h = 2166136261u;
  for (int k = 0; k < len; k++)
    h = (h ^ (unsigned char)s[k]) * 16777619u;
  return h;
}

void names_init(Names *t)
{
  *t = (Names){NULL, NULL, 0, 0};
}

void names_free(Names *t)
{
  free(t->slot);
  free(t->hash);
  names_init(t);
}

static bool same(NameRecords rec, int index, const char *name, int len)
{
  const char *s = rec.base + (size_t)index * rec.stride;
  return strncmp(s, name, (size_t)len) == 0 && s[len] == '\0';
}

int names_find(const Names *t, NameRecords rec, const char *name, int len)
{
  if (t->cap == 0)
    return -1;
  uint32_t h = hash_of(name, len);
  for (size_t i = h & (t->cap - 1);; i = (i + 1) & (t->cap - 1)) {
    if (t->slot[i] < 0)
      return -1;
    if (t->hash[i] == h && same(rec, t->slot[i], name, len))
      return t->slot[i];
  }
}

static void put(Names *t, int32_t index, uint32_t h)
{
  size_t i = h & (t->cap - 1);
  while (t->slot[i] >= 0)
    i = (i + 1) & (t->cap - 1);
  t->slot[i] = index;
  t->hash[i] = h;
  t->count++;
}

/* Double the table (64 slots at first), moving every entry. */
static bool grow(Names *t)
{
  Names bigger = {NULL, NULL, t->cap ? 2 * t->cap : 64, 0};
  bigger.slot = malloc(bigger.cap * sizeof *bigger.slot);
  bigger.hash = malloc(bigger.cap * sizeof *bigger.hash);
  if (!bigger.slot || !bigger.hash) {
    fprintf(stderr, "names: out of memory for %zu names\n", t->count + 1);
    names_free(&bigger);
    return false;
  }
  memset(bigger.slot, 0xff, bigger.cap * sizeof *bigger.slot); /* all -1 */
  for (size_t i = 0; i < t->cap; i++)
    if (t->slot[i] >= 0)
      put(&bigger, t->slot[i], t->hash[i]);
  names_free(t);
  *t = bigger;
  return true;
}

bool names_add(Names *t, NameRecords rec, int index)
{
  if (2 * (t->count + 1) > t->cap && !grow(t))
    return false;
  const char *name = rec.base + (size_t)index * rec.stride;
  put(t, index, hash_of(name, (int)strlen(name)));
  return true;
}
