/* Arrays that grow by doubling, their capacity never stored: an array of n
 * elements has room for the power of two at or above n, and at least 4.
 * The scene's materials, lights, planes and instances (common/scene.c) and
 * the parser's pending references (common/app/parser_state.c) grow this way. */
#ifndef RT_GROW_H
#define RT_GROW_H

#include <stdbool.h>
#include <stdlib.h>

/* The room an array of `count` elements has. */
static inline size_t grow_capacity(size_t count)
{
  size_t room = 4;
  while (room < count)
    room *= 2;
  return room;
}

/* Room for `more` elements after the `count` of *array (`size` bytes each);
 * allocates when *array is NULL. False when out of memory (*array kept). */
static inline bool grow_reserve(void **array, size_t count, size_t more, size_t size)
{
  size_t need = count + more;
  if (*array && need <= grow_capacity(count))
    return true;
  void *bigger = realloc(*array, grow_capacity(need) * size);
  if (!bigger)
    return false;
  *array = bigger;
  return true;
}

#endif
