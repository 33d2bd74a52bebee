/* Large arrays in transparent huge pages (common/pages.h). */
#define _DEFAULT_SOURCE /* madvise */
#include "pages.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

enum {
  HUGE_PAGE = 2 << 20,
  HUGE_ORDER = 9, /* 2 MB = 2^9 pages of 4 KB */
  ORDERS_MAX = 16,
};

size_t pages_free_huge(const char *text)
{
  size_t pages = 0;
  for (const char *line = text; line && *line;) {
    const char *zone = strstr(line, "zone");
    const char *eol = strchr(line, '\n');
    if (zone && (!eol || zone < eol)) {
      const char *s = zone + 4;
      while (*s == ' ')
        s++;
      while (*s && *s != ' ' && *s != '\n') /* the zone's name */
        s++;
      for (int order = 0; order < ORDERS_MAX; order++) {
        char *end;
        unsigned long long count = strtoull(s, &end, 10);
        if (end == s || (eol && end > eol))
          break;
        if (order >= HUGE_ORDER)
          pages += (size_t)count << order;
        s = end;
      }
    }
    line = eol ? eol + 1 : NULL;
  }
  return pages * 4096;
}

/* Whether a request of `bytes` should ask for huge pages: when the free
 * lists hold at least twice as much in blocks of 2 MB or more, each huge
 * page comes straight from them. With less, a fault on a region marked for
 * huge pages may stop to compact memory (the kernel's `defrag` setting
 * `madvise`, Debian's default), which earlier passes saw cost 0.2 s: the
 * array then stays in 4 KB pages. When the lists cannot be read, ask (the
 * kernel still decides). */
static int huge_ok(size_t bytes)
{
  FILE *f = fopen("/proc/buddyinfo", "r");
  if (!f)
    return 1;
  char text[4096];
  size_t len = fread(text, 1, sizeof text - 1, f);
  fclose(f);
  text[len] = '\0';
  return pages_free_huge(text) / 2 >= bytes;
}

void *pages_alloc(size_t bytes)
{
  if (bytes < HUGE_PAGE)
    return malloc(bytes ? bytes : 1);
  if (bytes > SIZE_MAX - HUGE_PAGE)
    return NULL;
  size_t rounded = (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
  void *p = aligned_alloc(HUGE_PAGE, rounded);
#ifdef MADV_HUGEPAGE
  if (p && huge_ok(rounded))
    madvise(p, rounded, MADV_HUGEPAGE); /* a hint: failure changes nothing */
#endif
  return p;
}
