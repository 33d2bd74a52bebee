/* Fresh memory mapped ahead of the writes (common/pages.h). */
#define _DEFAULT_SOURCE /* madvise */
#include "pages.h"

#include "threads.h"
#include <stdbool.h>
#include <stdint.h>
#include <sys/mman.h>
#include <unistd.h>

static uintptr_t page_size(void)
{
  long size = sysconf(_SC_PAGESIZE);
  return size > 0 ? (uintptr_t)size : 4096;
}

/* The whole pages of p[0 .. bytes): [*first, *end), empty when none. */
static void whole_pages(const void *p, size_t bytes, uintptr_t *first, uintptr_t *end,
                        uintptr_t *page)
{
  *page = page_size();
  *first = ((uintptr_t)p + *page - 1) & ~(*page - 1);
  *end = ((uintptr_t)p + bytes) & ~(*page - 1);
  if (!p || *end < *first)
    *end = *first;
}

/* madvise(advice) over the whole pages of p[0 .. bytes): in one call, or
 * (`parallel`) one block of whole pages per thread of an OpenMP team. */
static void advise(const void *p, size_t bytes, int advice, bool parallel)
{
  uintptr_t first, end, page;
  whole_pages(p, bytes, &first, &end, &page);
  if (!parallel) { /* no OpenMP construct: called from inside parallel loops */
    if (end > first)
      madvise((void *)first, end - first, advice);
    return;
  }
  size_t pages = (end - first) / page;
  int threads = omp_get_max_threads();
#pragma omp parallel for schedule(static, 1)
  for (int t = 0; t < threads; t++) {
    uintptr_t from = first + pages * (size_t)t / (size_t)threads * page;
    uintptr_t to = first + pages * (size_t)(t + 1) / (size_t)threads * page;
    if (to > from)
      madvise((void *)from, to - from, advice);
  }
}

void pages_populate(void *p, size_t bytes)
{
#ifdef MADV_POPULATE_WRITE
  advise(p, bytes, MADV_POPULATE_WRITE, false);
#else
  (void)p;
  (void)bytes;
#endif
}

void pages_populate_parallel(void *p, size_t bytes)
{
#ifdef MADV_POPULATE_WRITE
  advise(p, bytes, MADV_POPULATE_WRITE, true);
#else
  (void)p;
  (void)bytes;
#endif
}

/* A mapping of `bytes` spans whole pages, its last one included. */
static size_t mapped_length(size_t bytes)
{
  size_t page = page_size();
  return (bytes + page - 1) / page * page;
}

void pages_map_file_parallel(const void *p, size_t bytes)
{
#ifdef MADV_POPULATE_READ
  advise(p, mapped_length(bytes), MADV_POPULATE_READ, true);
#else
  (void)p;
  (void)bytes;
#endif
}

void pages_unmap_file_parallel(const void *p, size_t bytes)
{
  advise(p, mapped_length(bytes), MADV_DONTNEED, true);
}
