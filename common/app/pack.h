/* The speed pack's interface: what the program asks of the speed-ups. The
 * pack (fast/fast.c) implements it; a build with FAST=0 links the plain
 * answers of common/app/pack.c instead. Either way every test of a ray
 * against a shape is the shape's own function, and the pictures are the
 * same (docs/performance.md). */
#ifndef RT_PACK_H
#define RT_PACK_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include "film.h"
#include "scene.h"

/* film_init's contract (film.h): a zeroed film of width x height pixels,
 * freed by film_free; its pixels where they cost least to write. */
bool pack_film_init(Film *film, int width, int height);

/* Point scene->index at the query table of an index built over its
 * instances, which chooses the instances each query tests (shadow rays
 * toward an area light included: docs/performance.md), or leave it NULL:
 * the queries then test every instance in order. Call after scene_prepare;
 * the index is the pack's until pack_index_free. False (one line printed)
 * when out of memory. */
bool pack_index(Scene *scene);

/* Free the index pack_index built for scene and set scene->index to NULL;
 * harmless when there is none. Before scene_free. */
void pack_index_free(Scene *scene);

/* A line `sphere center X Y Z radius R material NAME` as the pack reads it
 * straight from the text: one space between words, plain decimals. */
typedef struct PackSphereLine {
  float v[4];         /* X, Y, Z and R, as the scene format's numbers read them */
  const char *name;   /* NAME: name_len bytes, up to the line's end */
  int name_len;
  int longest;        /* the length of its longest number or name */
  const char *next;   /* where the next line starts (or the text's end) */
} PackSphereLine;

/* Read the line at text[0 .. end - text) when it is such a line: true, *out
 * filled; false for any other line and for any doubt (the general parser
 * then reads it). The parser checks the values and the name as it checks its
 * own. */
bool pack_sphere_line(const char *text, const char *end, PackSphereLine *out);

/* Parse the `len` bytes of `text` into `scene` as parser_load_text does
 * (app/parser.h), in parts at once (parser_part_parse, parser_parts_join):
 * true, `scene` holds the scene the one-pass parse makes; false when left
 * to the one-pass parse (a small text, one thread, an error in the text:
 * that parse says what is wrong), nothing printed and `scene` as it was. */
bool pack_parse(const char *file, const char *text, size_t len, Scene *scene);

/* Map the `size` bytes of the regular file open at fd read-only: true, the
 * text at *text (nothing after its last byte); false to read it instead.
 * pack_unmap gives a mapped text back. */
bool pack_map(int fd, size_t size, char **text);
void pack_unmap(char *text, size_t size);

/* Row j (top row first) of a picture as its w * 3 bytes, RGB. */
typedef void (*PackRowFn)(const void *picture, int j, unsigned char *out);

/* Write the PNG of the w x h picture whose rows `row` gives to f: 1 when
 * written, 0 when it failed (errno, or ENOMEM), -1 when the pack leaves it
 * to the plain writer. */
int pack_png(FILE *f, int w, int h, PackRowFn row, const void *picture);

#endif
