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

/* parser_load_text without its check of the text's size, and always in
 * one pass (the parse every other is held to). */
bool parser_load_whole(const char *file, const char *text, size_t len, Scene *scene);

/* The same for a NUL-terminated string. */
bool parser_load_string(const char *file, const char *text, Scene *scene);

/* Read and parse the file at `path`. Same contract as parser_load_text; a
 * file that cannot be read whole prints `parser: cannot read 'PATH': REASON`. */
bool parser_load_file(const char *path, Scene *scene);

/* A large text parsed in parts at once (the speed pack's pack_parse,
 * app/pack.h): the text cut at line starts, each part parsed on its own,
 * the parts joined in file order. A part is a text's lines [from, to), each
 * of from and to 0, the text's length, or just after a '\n'. */
typedef struct ParserPart ParserPart;

/* Parse the lines text[from, to) (of a text `file` names) into a part of
 * their own, as parser_load_text parses a whole text but for this:
 * - nothing is printed: NULL when the lines hold an error, more shapes than
 *   n_room or when memory runs out (the one-pass parse of the whole text,
 *   parser_load_whole, then says what is wrong);
 * - the part's shapes are written at room[0 .. n_room), at most one a line,
 *   an array the part does not own;
 * - the materials of `given` (NULL, or the part parsed from the text's
 *   start) count as defined before the part's first line; a shape that
 *   names a material the part has not seen yet keeps its name, for
 *   parser_parts_join to resolve;
 * - from 0 is the text's start: a byte-order mark there is skipped.
 * Parts of one text may be parsed at once on several threads (each reads
 * `given`, and writes its part and its room only). */
ParserPart *parser_part_parse(const char *file, const char *text, size_t from, size_t to,
                              const ParserPart *given, struct Instance *room, int n_room);

/* The shapes a part holds: room[0 .. that) of the room it was given. */
int parser_part_shapes(const ParserPart *part);

/* Free a part (not its room); harmless with NULL. */
void parser_part_free(ParserPart *part);

/* Join parts[0 .. n) (each parsed, none NULL) into `scene` (freshly
 * scene_init'ed): parts[0] from the text's start, each next one from where
 * the last ended, each given parts[0] or nothing, their rooms in file order
 * in `instances`, none starting before the end of the shapes of the parts
 * before it (consecutive stretches are such; each part's shapes are moved
 * down to follow the last part's, and nothing moves where the rooms were
 * full). `instances`: an array from malloc or aligned_alloc with room for
 * grow_capacity(N) (common/grow.h), N at least the end of the last room.
 * True: `scene` holds the scene parser_load_whole makes of the whole text
 * (instances in file order, every value the same) and owns `instances`.
 * False when the whole text holds an error that no part alone shows (a
 * material defined in two parts, a once-statement in two, a material named
 * nowhere defined) or memory ran out: nothing printed, `scene` as it was,
 * `instances` the caller's. The parts are the caller's to free either way. */
bool parser_parts_join(ParserPart *const *parts, int n, struct Instance *instances,
                       Scene *scene);

#endif
