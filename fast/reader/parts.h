/* A large scene text parsed in parts at once, on several threads, and
 * joined in file order (pack_parse, app/pack.h): the parser's own parts
 * (parser_part_parse, parser_parts_join, app/parser.h). */
#ifndef RT_PARTS_H
#define RT_PARTS_H

#include <stdbool.h>
#include <stddef.h>

#include "scene.h"

/* pack_parse: a text of at least two pieces of PARTS_PIECE_MIN bytes, on
 * two threads or more, parsed by parts_load in up to four pieces a thread;
 * false (nothing printed, `scene` as it was) otherwise, or when parts_load
 * leaves the text to the one-pass parse. */
bool parts_parse(const char *file, const char *text, size_t len, Scene *scene);

/* The text cut in `pieces` pieces (at least 2, at most PARTS_PIECES_MAX),
 * each parsed as a part on whichever thread is free, joined in file order:
 * true, `scene` (freshly scene_init'ed) the one-pass parse's scene; false
 * when an error is in the text (the one-pass parse says which), the text
 * is too short to cut, or memory runs out: nothing printed, `scene` as it
 * was. */
bool parts_load(const char *file, const char *text, size_t len, Scene *scene, int pieces);

enum {
  PARTS_PIECE_MIN = 1 << 21, /* bytes: smaller texts are parsed in one pass */
  PARTS_PIECES_MAX = 64,
};

#endif
