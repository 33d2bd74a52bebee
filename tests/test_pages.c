/* Fresh memory mapped ahead of the writes (common/pages.h): after
 * pages_populate the whole pages of the range are resident (mincore) and
 * what they held is kept; pages outside it stay unmapped. A file's pages
 * entered in the page table and taken out again by the threads (present
 * bits of /proc/self/pagemap). docs/reliability.md, "Eighth pass", "Ninth
 * pass". */
#define _DEFAULT_SOURCE /* mincore, MAP_ANONYMOUS */
#include "check.h"

#include <errno.h>
#include <fcntl.h>
#include "threads.h"
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

#include "pages.h"

#define DOC "docs/reliability.md, \"Eighth pass\""

enum { PAGES = 64 };

/* Resident pages among p[0 .. pages) pages. */
static int resident(unsigned char *p, int pages, long size)
{
  unsigned char in[PAGES];
  cr_assert(mincore(p, (size_t)pages * (size_t)size, in) == 0);
  int n = 0;
  for (int k = 0; k < pages; k++)
    n += in[k] & 1;
  return n;
}

static unsigned char *fresh(long size)
{
  void *p = mmap(NULL, (size_t)PAGES * (size_t)size, PROT_READ | PROT_WRITE,
                 MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  cr_assert(p != MAP_FAILED);
  return p;
}

/* The kernel's MADV_POPULATE_WRITE (Linux 5.14 on); without it
 * pages_populate does nothing, and these tests have nothing to check. */
static bool kernel_populates(long size)
{
#ifdef MADV_POPULATE_WRITE
  unsigned char *p = fresh(size);
  bool ok = madvise(p, (size_t)size, MADV_POPULATE_WRITE) == 0;
  munmap(p, (size_t)PAGES * (size_t)size);
  return ok;
#else
  (void)size;
  return false;
#endif
}

/* A fresh mapping of PAGES pages (*size bytes each), or the test skipped
 * where the kernel cannot populate. */
static unsigned char *fresh_or_skip(long *size)
{
  *size = sysconf(_SC_PAGESIZE);
  if (!kernel_populates(*size))
    cr_skip("this kernel has no MADV_POPULATE_WRITE");
  return fresh(*size);
}

Test(pages, populate_maps_the_whole_pages_of_the_range)
{
  long size;
  unsigned char *p = fresh_or_skip(&size);
  Check c = CHECK("pages_populate", DOC);
  CHECK_INT(&c, 0, resident(p, PAGES, size), "resident pages of a fresh mapping");
  p[10 * size + 5] = 42; /* page 10 written before */
  /* From the middle of page 8 to the middle of page 20: whole pages 9 to 19. */
  pages_populate(p + 8 * size + size / 2, (size_t)(12 * size));
  CHECK_INT(&c, 11, resident(p, PAGES, size),
            "resident pages after populating pages 9 to 19 (page 10 among them, written before)");
  unsigned char in[PAGES];
  cr_assert(mincore(p, (size_t)PAGES * (size_t)size, in) == 0);
  CHECK_INT(&c, 0, in[8] & 1, "page 8, half in the range: resident (1) or not (0)");
  CHECK_INT(&c, 0, in[20] & 1, "page 20, half in the range: resident (1) or not (0)");
  CHECK_INT(&c, 42, p[10 * size + 5], "the byte written before populating");
  CHECK_INT(&c, 0, p[15 * size], "a populated byte never written");
  munmap(p, (size_t)PAGES * (size_t)size);
  CHECK_DONE(&c);
}

Test(pages, populate_parallel_covers_the_range)
{
  long size;
  unsigned char *p = fresh_or_skip(&size);
  Check c = CHECK("pages_populate_parallel", DOC);
  pages_populate_parallel(p, (size_t)(48 * size));
  CHECK_INT(&c, 48, resident(p, PAGES, size), "resident pages after populating pages 0 to 47");
  pages_populate(NULL, 100); /* nothing to map: no effect, no crash */
  munmap(p, (size_t)PAGES * (size_t)size);
  CHECK_DONE(&c);
}

/* Pages of p[0 .. pages) whose page table entry is present (bit 63 of
 * /proc/self/pagemap), or the test skipped where that file cannot be read. */
static int present(const unsigned char *p, int pages, long size)
{
  int fd = open("/proc/self/pagemap", O_RDONLY);
  if (fd < 0)
    cr_skip("no /proc/self/pagemap to read");
  uint64_t e[PAGES];
  ssize_t got = pread(fd, e, (size_t)pages * sizeof e[0],
                      (off_t)((uintptr_t)p / (uintptr_t)size * sizeof e[0]));
  close(fd);
  cr_assert(got == (ssize_t)((size_t)pages * sizeof e[0]), "pagemap: short read");
  int n = 0;
  for (int k = 0; k < pages; k++)
    n += (int)(e[k] >> 63);
  return n;
}

Test(pages, file_pages_entered_and_taken_out_by_the_threads)
{
  long size = sysconf(_SC_PAGESIZE);
  size_t bytes = (size_t)PAGES * (size_t)size;
  char path[] = "/tmp/rt-pages-XXXXXX";
  int fd = mkstemp(path);
  cr_assert(fd >= 0, "mkstemp: %s", strerror(errno));
  unlink(path);
  unsigned char *text = malloc(bytes);
  cr_assert(text);
  for (size_t k = 0; k < bytes; k++)
    text[k] = (unsigned char)(k * 7 + k / 4096);
  cr_assert(write(fd, text, bytes) == (ssize_t)bytes, "write: %s", strerror(errno));
  const unsigned char *p = mmap(NULL, bytes, PROT_READ, MAP_PRIVATE, fd, 0);
  cr_assert(p != MAP_FAILED);
  close(fd);
#ifdef MADV_POPULATE_READ
  if (madvise((void *)(uintptr_t)p, (size_t)size, MADV_POPULATE_READ) != 0)
    cr_skip("this kernel has no MADV_POPULATE_READ");
  madvise((void *)(uintptr_t)p, bytes, MADV_DONTNEED); /* and the neighbours the kernel mapped along */
#else
  cr_skip("no MADV_POPULATE_READ here");
#endif
  Check c = CHECK("pages_map_file_parallel, pages_unmap_file_parallel", DOC);
  CHECK_INT(&c, 0, present(p, PAGES, size), "present pages of a fresh mapping of the file");
  int threads = omp_get_max_threads();
  omp_set_num_threads(3); /* blocks of 21, 21 and 22 pages */
  pages_map_file_parallel(p, bytes);
  CHECK_INT(&c, PAGES, present(p, PAGES, size), "present pages after pages_map_file_parallel");
  pages_unmap_file_parallel(p, bytes);
  CHECK_INT(&c, 0, present(p, PAGES, size), "present pages after pages_unmap_file_parallel");
  omp_set_num_threads(threads);
  CHECK_INT(&c, 0, memcmp(p, text, bytes) != 0, "the mapping differs from the file (1) or not (0)");
  munmap((void *)(uintptr_t)p, bytes);
  free(text);
  CHECK_DONE(&c);
}
