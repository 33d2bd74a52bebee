/* A large scene file mapped read-only (reader/mapped.h). */
#include "reader/mapped.h"

#include <sys/mman.h>

bool mapped_open(int fd, size_t size, char **text)
{
  void *p = mmap(NULL, size, PROT_READ, MAP_PRIVATE, fd, 0);
  if (p == MAP_FAILED)
    return false;
  *text = p;
  return true;
}

void mapped_close(char *text, size_t size)
{
  munmap(text, size);
}
