/* Large blocks in 2 MB pages (memory/huge.h). */
#define _DEFAULT_SOURCE /* madvise */
#include "memory/huge.h"

#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

enum { HUGE_PAGE = 2 << 20 };

void *huge_alloc(size_t bytes)
{
  if (bytes < HUGE_PAGE)
    return NULL;
  size_t rounded = (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
  void *p = aligned_alloc(HUGE_PAGE, rounded);
  if (!p)
    return NULL;
#ifdef MADV_HUGEPAGE
  madvise(p, rounded, MADV_HUGEPAGE); /* a hint: failure changes nothing */
#endif
  return p;
}

void *huge_zeroed(size_t bytes)
{
  void *p = huge_alloc(bytes);
  if (p)
    memset(p, 0, bytes);
  return p;
}
