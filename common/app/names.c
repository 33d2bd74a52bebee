/* Material names of a scene file in a hash table (step 02): short names as
 * their own keys, longer ones by FNV-1a hash, linear probing, the table at
 * most half full. docs/scene-format.md. */
#include "app/names.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { SHORT_MAX = 7 }; /* bytes: a name this short is its own key */

/* A name as one number. Up to 7 bytes: the bytes themselves and, in the top
 * byte, the length plus one, so that two short names have the same key only
 * when they are the same name, and no strncmp is needed to tell (the names
 * of a large scene's sphere lines are such: "red", "white"). Longer: its
 * FNV-1a hash, top byte 0, checked with strncmp. */
static uint64_t key_of(const char *s, int len)
{
  if (len <= SHORT_MAX) {
    uint64_t k = (uint64_t)(len + 1) << 56;
    for (int i = 0; i < len; i++)
      k |= (uint64_t)(unsigned char)s[i] << (8 * i);
    return k;
  }
  uint32_t h = 2166136261u;
  for (int k = 0; k < len; k++)
    h = (h ^ (unsigned char)s[k]) * 16777619u;
  return h;
}

/* The first slot to look at for a key: the top half of its product with
 * 2^64 / golden ratio (Fibonacci hashing: every bit of the key moves it),
 * taken modulo the table's size. */
static size_t home(const Names *t, uint64_t key)
{
  return (size_t)((key * 0x9E3779B97F4A7C15ull) >> 32) & (t->cap - 1);
}

void names_init(Names *t)
{
  *t = (Names){NULL, NULL, 0, 0};
}

void names_free(Names *t)
{
  free(t->slot);
  free(t->key);
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
  uint64_t key = key_of(name, len);
  for (size_t i = home(t, key);; i = (i + 1) & (t->cap - 1)) {
    if (t->slot[i] < 0)
      return -1;
    if (t->key[i] == key && (len <= SHORT_MAX || same(rec, t->slot[i], name, len)))
      return t->slot[i];
  }
}

static void put(Names *t, int32_t index, uint64_t key)
{
  size_t i = home(t, key);
  while (t->slot[i] >= 0)
    i = (i + 1) & (t->cap - 1);
  t->slot[i] = index;
  t->key[i] = key;
  t->count++;
}

/* Double the table (64 slots at first), moving every entry. */
static bool grow(Names *t)
{
  Names bigger = {NULL, NULL, t->cap ? 2 * t->cap : 64, 0};
  bigger.slot = malloc(bigger.cap * sizeof *bigger.slot);
  bigger.key = malloc(bigger.cap * sizeof *bigger.key);
  if (!bigger.slot || !bigger.key) {
    fprintf(stderr, "names: out of memory for %zu names\n", t->count + 1);
    names_free(&bigger);
    return false;
  }
  memset(bigger.slot, 0xff, bigger.cap * sizeof *bigger.slot); /* all -1 */
  for (size_t i = 0; i < t->cap; i++)
    if (t->slot[i] >= 0)
      put(&bigger, t->slot[i], t->key[i]);
  names_free(t);
  *t = bigger;
  return true;
}

bool names_add(Names *t, NameRecords rec, int index)
{
  if (2 * (t->count + 1) > t->cap && !grow(t))
    return false;
  const char *name = rec.base + (size_t)index * rec.stride;
  put(t, index, key_of(name, (int)strlen(name)));
  return true;
}
