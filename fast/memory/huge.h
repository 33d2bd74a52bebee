/* Large blocks in 2 MB pages where the kernel offers them (transparent huge
 * pages): the film's pixels (pack_film_init, app/pack.h), the shapes of a
 * large scene (reader/parts.c). Otherwise the first write to each 4 KB page
 * of a new block is a page fault, which for these blocks costs more than
 * the few faults of 2 MB pages. */
#ifndef RT_HUGE_H
#define RT_HUGE_H

#include <stddef.h>

/* `bytes` bytes, aligned to 2 MB, freed by free() (and grown by realloc);
 * NULL when the block is smaller than one such page (plain malloc serves it
 * as well) or memory runs out. */
void *huge_alloc(size_t bytes);

/* huge_alloc's block, zeroed. */
void *huge_zeroed(size_t bytes);

#endif
