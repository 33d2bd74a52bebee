/* Large arrays in 2 MB pages (common/pages.h): the free memory the kernel's
 * buddy lists hold in blocks of 2 MB or more, counted by hand from the text
 * of /proc/buddyinfo, and the allocations themselves (aligned, usable, NULL
 * when too large). docs/reliability.md, "Large scenes". */
#include "check.h"

#include <stdlib.h>

#include "pages.h"

#define DOC "docs/reliability.md, \"Large scenes\""

static const double MB = 1024.0 * 1024.0;

Test(pages, free_huge_blocks_from_buddyinfo)
{
  Check c = CHECK("pages_free_huge", DOC);
  /* One machine's text: orders 9 (2 MB) and 10 (4 MB) count, in every zone.
   * DMA 1 x 2 + 3 x 4 = 14 MB, DMA32 2 x 2 + 752 x 4 = 3012 MB, Normal
   * 162 x 2 + 280 x 4 = 1444 MB: 4470 MB. */
  const char *machine =
      "Node 0, zone      DMA      0      0      0      0      0      0      0      0      1      1      3 \n"
      "Node 0, zone    DMA32      2      2      4      2      5      4      3      3      4      2    752 \n"
      "Node 0, zone   Normal  11483   4606   2126    740    350    202     81     41     89    162    280 \n";
  CHECK_INT(&c, 4470, pages_free_huge(machine) / MB, "MB free in blocks of 2 MB or more");
  /* A kernel with an order 11 (8 MB blocks); no final newline. */
  CHECK_INT(&c, 2 + 8 + 16, pages_free_huge("Node 0, zone Normal 9 9 9 9 9 9 9 9 9 1 2 2") / MB,
            "MB with orders 9 to 11 (1 x 2 + 2 x 4 + 2 x 8)");
  CHECK_INT(&c, 0, pages_free_huge("Node 0, zone Normal 7 7 7 7 7 7 7 7 7 0 0\n"),
            "bytes when every free block is smaller than 2 MB");
  CHECK_INT(&c, 0, pages_free_huge(""), "bytes of an empty text");
  CHECK_INT(&c, 0, pages_free_huge("no zones here\n"), "bytes of a text with no zone line");
  CHECK_INT(&c, 2, pages_free_huge("Node 0, zone DMA 0 0 0 0 0 0 0 0 0 1\nNode 1, zone\n") / MB,
            "MB when a zone line has no counts");
}

Test(pages, allocations)
{
  Check c = CHECK("pages_alloc", DOC);
  size_t sizes[] = {1, 4096, (2u << 20) - 1, 2u << 20, (5u << 20) + 3};
  for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
    unsigned char *p = pages_alloc(sizes[k]);
    CHECK_THAT(&c, p != NULL, "%zu bytes: expected room, got NULL", sizes[k]);
    if (!p)
      continue;
    if (sizes[k] >= 2u << 20)
      CHECK_INT(&c, 0, (uintptr_t)p % (2u << 20), "%zu bytes: the address modulo 2 MB",
                sizes[k]);
    p[0] = 1;
    p[sizes[k] - 1] = 2; /* the last byte is ours (ASan and Valgrind see it) */
    CHECK_THAT(&c, p[sizes[k] - 1] == 2 && p[0] == (sizes[k] > 1 ? 1 : 2),
               "%zu bytes: expected the first and last bytes to keep what was written",
               sizes[k]);
    free(p);
  }
  CHECK_THAT(&c, pages_alloc(SIZE_MAX) == NULL && pages_alloc(SIZE_MAX - (1u << 20)) == NULL,
             "a request near SIZE_MAX: expected NULL");
  CHECK_DONE(&c);
}
