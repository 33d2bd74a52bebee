/* A large scene file mapped read-only (reader/mapped.h). */
#include "reader/mapped.h"

#include <sys/mman.h>

#include "pages/pages.h"

bool mapped_open(int fd, size_t size, char **text)
{
  void *p = mmap(NULL, size, PROT_READ, MAP_PRIVATE, fd, 0);
  if (p == MAP_FAILED)
    return false;
  pages_map_file_parallel(p, size);
  *text = p;
  return true;
}

void mapped_close(char *text, size_t size)
{
  pages_unmap_file_parallel(text, size);
  munmap(text, size);
}
