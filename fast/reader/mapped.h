/* A large scene file mapped read-only instead of read into a new buffer: no
 * copy of its bytes. */
#ifndef RT_MAPPED_H
#define RT_MAPPED_H

#include <stdbool.h>
#include <stddef.h>

/* Map the `size` bytes of the regular file open at fd: true, the text at
 * *text; false (nothing mapped) when the system cannot. */
bool mapped_open(int fd, size_t size, char **text);

/* Give back a text mapped_open mapped. */
void mapped_close(char *text, size_t size);

#endif
