/* Scene-file parser (the format of docs/scene-format.md). Every error is one
 * line `FILE:LINE:COL: expected ..., found ...`. Introduced in step 02. */
#ifndef RT_PARSER_H
#define RT_PARSER_H

#include <stdbool.h>
#include <stddef.h>
#include "scene.h"

/* Largest scene file or text, in bytes: lines and columns stay ints. */
#define PARSER_MAX_BYTES ((size_t)2147483647)

/* Parse the `len` bytes of `text` (NUL bytes in it are errors) into `scene`,
 * which must be freshly scene_init'ed; `file` names the text in messages. On
 * error prints one line to stderr, frees what was built and returns false. */
bool parser_load_text(const char *file, const char *text, size_t len, Scene *scene);

/* parser_load_text without its check of the text's size. */
bool parser_load_whole(const char *file, const char *text, size_t len, Scene *scene);

/* The same for a NUL-terminated string. */
bool parser_load_string(const char *file, const char *text, Scene *scene);

/* Read and parse the file at `path`. Same contract as parser_load_text; a
 * file that cannot be read whole prints `parser: cannot read 'PATH': REASON`. */
bool parser_load_file(const char *path, Scene *scene);

#endif
