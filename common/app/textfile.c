/* A whole file as text (step 02): a regular file read at its known size
 * (or mapped, when large, by the speed pack), pipes and devices into a
 * growing buffer.
 * docs/scene-format.md. */
#include "app/textfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/pack.h"

typedef struct Buf {
  char *s;
  size_t len, cap;
} Buf;

/* Room for `more` bytes past the text and a terminator; false (errno
 * ENOMEM) when memory runs out. */
static bool reserve(Buf *b, size_t more)
{
  if (b->len + more < b->cap)
    return true;
  size_t cap = b->cap ? 2 * b->cap : 65536;
  if (cap < b->len + more + 1)
    cap = b->len + more + 1;
  char *bigger = realloc(b->s, cap);
  if (!bigger) {
    errno = ENOMEM;
    return false;
  }
  b->s = bigger;
  b->cap = cap;
  return true;
}

/* Read what fd holds (`hint` bytes expected); false with errno set. One byte
 * past `max` is enough to know the file is too large. Stops after a NUL. */
static bool read_all(int fd, size_t hint, size_t max, Buf *b)
{
  if (!reserve(b, hint + 1))
    return false;
  for (;;) {
    if (b->len + 1 == b->cap && !reserve(b, 1))
      return false;
    size_t room = b->cap - 1 - b->len;
    if (room > max + 1 - b->len)
      room = max + 1 - b->len;
    ssize_t got = read(fd, b->s + b->len, room);
    if (got < 0 && errno == EINTR)
      continue;
    if (got <= 0)
      return got == 0;
    bool nul = memchr(b->s + b->len, '\0', (size_t)got) != NULL;
    b->len += (size_t)got;
    if (b->len > max) {
      errno = EFBIG;
      return false;
    }
    if (nul)
      return true;
  }
}

enum { MAP_FROM = 8 << 20 }; /* bytes: the pack may map a regular file this large */

int textfile_read(const char *path, size_t max, TextFile *f)
{
  *f = (TextFile){0};
  int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    return errno;
  struct stat st;
  Buf b = {NULL, 0, 0};
  bool ok = fstat(fd, &st) == 0;
  if (ok && S_ISREG(st.st_mode) && (uintmax_t)st.st_size > max) {
    ok = false;
    errno = EFBIG;
  }
  size_t hint = ok && S_ISREG(st.st_mode) ? (size_t)st.st_size : 0;
  if (ok && hint >= MAP_FROM && pack_map(fd, hint, &f->text)) {
    f->len = hint;
    f->mapped = true;
    close(fd);
    return 0;
  }
  ok = ok && read_all(fd, hint, max, &b);
  int err = ok ? 0 : errno;
  close(fd);
  if (!ok) {
    free(b.s);
    return err;
  }
  b.s[b.len] = '\0';
  *f = (TextFile){.text = b.s, .len = b.len};
  return 0;
}

void textfile_free(TextFile *f)
{
  if (f->mapped)
    pack_unmap(f->text, f->len);
  else
    free(f->text);
  *f = (TextFile){0};
}
