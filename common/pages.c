/* Fresh memory mapped ahead of the writes (common/pages.h). */
#define _DEFAULT_SOURCE /* madvise */
#include "pages.h"

#include <omp.h>
#include <stdint.h>
#include <sys/mman.h>
#include <unistd.h>

void pages_populate(void *p, size_t bytes)
{
#ifdef MADV_POPULATE_WRITE
  long size = sysconf(_SC_PAGESIZE);
  uintptr_t page = size > 0 ? (uintptr_t)size : 4096;
  uintptr_t first = ((uintptr_t)p + page - 1) & ~(page - 1);
  uintptr_t end = ((uintptr_t)p + bytes) & ~(page - 1);
  if (p && end > first)
    madvise((void *)first, end - first, MADV_POPULATE_WRITE);
#else
  (void)p;
  (void)bytes;
#endif
}

void pages_populate_parallel(void *p, size_t bytes)
{
  char *c = p;
  int threads = omp_get_max_threads();
#pragma omp parallel for schedule(static, 1)
  for (int t = 0; t < threads; t++) {
    size_t from = bytes / (size_t)threads * (size_t)t;
    size_t to = t + 1 == threads ? bytes : bytes / (size_t)threads * (size_t)(t + 1);
    pages_populate(c + from, to - from);
  }
}

/* madvise(advice) over p[0 .. bytes) in one page-aligned block per thread. */
static void advise_parallel(const void *p, size_t bytes, int advice)
{
  long size = sysconf(_SC_PAGESIZE);
  size_t page = size > 0 ? (size_t)size : 4096;
  int threads = omp_get_max_threads();
#pragma omp parallel for schedule(static, 1)
  for (int t = 0; t < threads; t++) {
    size_t from = bytes / (size_t)threads * (size_t)t / page * page;
    size_t to = t + 1 == threads ? bytes : bytes / (size_t)threads * (size_t)(t + 1) / page * page;
    if (to > from)
      madvise((char *)(uintptr_t)p + from, to - from, advice);
  }
}

void pages_map_file_parallel(const void *p, size_t bytes)
{
#ifdef MADV_POPULATE_READ
  advise_parallel(p, bytes, MADV_POPULATE_READ);
#else
  (void)p;
  (void)bytes;
#endif
}

void pages_unmap_file_parallel(const void *p, size_t bytes)
{
  advise_parallel(p, bytes, MADV_DONTNEED);
}
