/* Fresh memory mapped ahead of the loop that writes it. The first write to
 * each 4 KB page of a new array is a page fault, and a 10^6-sphere scene
 * takes tens of thousands of them; asking the kernel for a block's pages in
 * one call (madvise MADV_POPULATE_WRITE, Linux 5.14 on) costs less than
 * faulting them one by one, and each thread asks for the block it is about
 * to write. */
#ifndef RT_PAGES_H
#define RT_PAGES_H

#include <stddef.h>

/* The whole pages of p[0 .. bytes), mapped and writable now. A hint: where
 * the kernel cannot, the writes fault them in as before. */
void pages_populate(void *p, size_t bytes);

/* pages_populate in one block of whole pages per thread of an OpenMP team. */
void pages_populate_parallel(void *p, size_t bytes);

/* A file mapped read-only at p (page aligned, `bytes` long): its pages
 * entered in the page table now, one block per thread of an OpenMP team
 * (MADV_POPULATE_READ), where MAP_POPULATE does it on one thread; and,
 * ahead of munmap, taken out again the same way (MADV_DONTNEED: the file's
 * pages stay in the page cache). Hints: where the kernel cannot, the reads
 * fault the pages in, and munmap takes them out. */
void pages_map_file_parallel(const void *p, size_t bytes);
void pages_unmap_file_parallel(const void *p, size_t bytes);

#endif
