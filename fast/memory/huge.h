/* Large zeroed blocks in 2 MB pages where the kernel offers them
 * (transparent huge pages): the film's pixels (pack_film_init, app/pack.h).
 * Otherwise the first write to each 4 KB page of a new block is a page
 * fault, which for a film costs more than the few faults and the memset. */
#ifndef RT_HUGE_H
#define RT_HUGE_H

#include <stddef.h>

/* `bytes` zeroed bytes, aligned to 2 MB, freed by free(); NULL when the
 * block is smaller than one such page (plain calloc serves it as well) or
 * memory runs out. */
void *huge_zeroed(size_t bytes);

#endif
