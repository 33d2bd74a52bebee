/* Large arrays in 2 MB pages (transparent huge pages) where the kernel has
 * them free: the first write to a fresh 4 KB page is a page fault, and the
 * arrays of a 10^6-sphere scene take about 30 000 of them
 * (docs/reliability.md, "Large scenes"). */
#ifndef RT_PAGES_H
#define RT_PAGES_H

#include <stddef.h>

/* Room for `bytes` (not cleared), released with free(). From 2 MB on, on a
 * 2 MB boundary and marked for huge pages when pages_huge_ok says the
 * kernel has them free; smaller ones come from malloc. NULL when out of
 * memory. */
void *pages_alloc(size_t bytes);

/* Free memory in blocks of 2 MB or more, in bytes, as the text of
 * /proc/buddyinfo lists it (count of free blocks per order, order 0 = one
 * 4 KB page); 0 for a text that lists none. */
size_t pages_free_huge(const char *buddyinfo);

#endif
