/* A whole file read into memory as text (the scene files, step 02), never a
 * truncated one: a file that does not fit is an error, not a shorter text.
 * docs/scene-format.md, "Errors". */
#ifndef RT_TEXTFILE_H
#define RT_TEXTFILE_H

#include <stddef.h>

/* Read `path` into a new NUL-terminated buffer (*text, the caller frees it
 * with free()), *len bytes before the terminator. Reading stops after the
 * first NUL byte, which a text cannot hold (the caller's lexer reports it
 * where it is), so `--scene /dev/zero` ends at once. Returns 0, or an errno
 * value: EFBIG when the file has more than `max` bytes, ENOMEM when memory
 * runs out, the system's reason otherwise (ENOENT, EISDIR, EACCES, ...). */
int textfile_read(const char *path, size_t max, char **text, size_t *len);

#endif
