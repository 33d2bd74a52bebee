/* A large scene text parsed in parallel pieces and merged (the speed pack's
 * large-scene reader, pack_parse in app/pack.h). */
#ifndef RT_PIECES_H
#define RT_PIECES_H

#include <stdbool.h>
#include <stddef.h>
#include "scene.h"

/* parser_load_text cut into `chunks` pieces at line starts, parsed at once
 * (OpenMP) and merged; any error, in a piece or between pieces (a second
 * `film`, a material defined twice, a name left undefined), and the text is
 * parsed again whole (parser_load_whole), which prints the error as usual.
 * The tests compare it with the one-piece parse on every case. */
bool pieces_load(const char *file, const char *text, size_t len, Scene *scene, int chunks);

/* A text of at least two pieces' worth on a machine of two threads or more:
 * true, *ok pieces_load's verdict; false (nothing done) otherwise. */
bool pieces_parse(const char *file, const char *text, size_t len, Scene *scene, bool *ok);

/* How many times pieces_load has parsed a text again whole after its pieces
 * failed: on an error, which the whole parse then prints, and never for a
 * valid scene (the tests check; a miscounted piece's room would show there
 * and nowhere else, as a parse twice as slow). */
extern int pieces_reparses;

/* References to materials that the pieces of pieces_load left to resolve
 * after parsing, summed over every call: none to the materials of the lines
 * before the first sphere, which every piece is given (the tests check). */
extern int pieces_pending;

#endif
