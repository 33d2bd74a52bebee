/* A whole file in memory as text (the scene files, step 02): read, or mapped
 * when large; never a truncated one: a file that does not fit is an error,
 * not a shorter text. docs/scene-format.md, "Errors". */
#ifndef RT_TEXTFILE_H
#define RT_TEXTFILE_H

#include <stdbool.h>
#include <stddef.h>

/* The text of a file: text[0 .. len). A file read is followed by a NUL byte
 * (text[len]); a large regular file is mapped read-only instead, with
 * nothing after its last byte. Free it with textfile_free. */
typedef struct TextFile {
  char *text;
  size_t len;
  bool mapped;
} TextFile;

/* Read `path` into *f. Reading stops after the first NUL byte, which a text
 * cannot hold (the caller's lexer reports it where it is), so `--scene
 * /dev/zero` ends at once; a mapped file is whole (the lexer stops there
 * too). Returns 0, or an errno value: EFBIG when the file has more than `max`
 * bytes, ENOMEM when memory runs out, the system's reason otherwise (ENOENT,
 * EISDIR, EACCES, ...); *f is then empty. */
int textfile_read(const char *path, size_t max, TextFile *f);

/* Unmap or free f's text; *f is left empty. */
void textfile_free(TextFile *f);

#endif
