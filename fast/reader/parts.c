/* A large scene text parsed in pieces at once (reader/parts.h). The lines
 * before the first sphere line, when they are short, are parsed first, as
 * the header part, whose materials every other part is given: their shapes
 * then find their materials at once. The shapes go in place to one array,
 * one slot a line, in 2 MB pages: each part writes its own stretch (the
 * pieces' after the header's shapes), and the join moves nothing where a
 * piece's lines are all shapes. */
#define _GNU_SOURCE /* memmem */
#include "reader/parts.h"

#include <stdlib.h>
#include <string.h>

#include "app/parser.h"
#include "grow.h"
#include "memory/huge.h"
#include "shapes.h"
#include "threads.h"

enum { PIECES_PER_THREAD = 4 }; /* taken in turn: a slow core holds up less */

/* Piece boundaries in text[from .. len), each just after a '\n':
 * start[0 .. n], start[0] = from, start[n] = len. The pieces shrink as the
 * parse goes on (piece k of `want` about (2 (want - k) - 1) / want^2 of the
 * text), so that the threads, taking them in turn, finish close together: a
 * thread the machine slows down holds the others up by at most one small
 * piece. */
static int cut_pieces(const char *text, size_t from, size_t len, int want, size_t *start)
{
  int n = 1;
  start[0] = from;
  for (int k = 1; k < want; k++) {
    /* (len - from) k (2 want - k) / want^2: below 2^31 times 2^13 */
    unsigned long long share = (unsigned long long)k * (unsigned)(2 * want - k);
    size_t at = from + (size_t)((len - from) * share / ((unsigned long long)want * want));
    const char *nl = at > start[n - 1] ? memchr(text + at, '\n', len - at) : NULL;
    if (nl && (size_t)(nl - text) + 1 < len)
      start[n++] = (size_t)(nl - text) + 1;
  }
  start[n] = len;
  return n;
}

/* The header: the lines before the first that starts with a sphere, when it
 * starts within the first `limit` bytes; 0 otherwise. */
static size_t header_length(const char *text, size_t len, size_t limit)
{
  static const char word[] = "\nsphere ";
  if (len < limit)
    limit = len;
  const char *at = memmem(text, limit, word, sizeof word - 1);
  return at ? (size_t)(at - text) + 1 : 0;
}

/* Lines in text[0 .. len): its newlines, plus one for a last line without
 * one. Counted 255 bytes at a time in one byte, which the compiler turns
 * into vector compares. */
static int count_lines(const char *text, size_t len)
{
  size_t n = 0;
  for (size_t k = 0; k < len;) {
    size_t end = len - k < 255 ? len : k + 255;
    unsigned char in_block = 0;
    for (; k < end; k++)
      in_block += text[k] == '\n';
    n += in_block;
  }
  return (int)n + (len > 0 && text[len - 1] != '\n');
}

/* Room for `count` instances as a growing array of that many
 * (common/grow.h), in 2 MB pages when it is large. */
static Instance *shapes_array(int count)
{
  size_t bytes = grow_capacity((size_t)count) * sizeof(Instance);
  Instance *a = huge_alloc(bytes);
  return a ? a : malloc(bytes);
}

bool parts_load(const char *file, const char *text, size_t len, Scene *scene, int pieces)
{
  if (pieces < 2)
    return false;
  int want = pieces < PARTS_PIECES_MAX ? pieces : PARTS_PIECES_MAX;
  /* A header of at most a sixteenth of a piece's mean share (parsed alone,
   * while the other threads wait) becomes part 0: h = 1. */
  size_t start[PARTS_PIECES_MAX + 2];
  size_t head = header_length(text, len, len / ((size_t)want * 16));
  int h = head > 0;
  start[0] = 0;
  int n = h + cut_pieces(text, head, len, want, start + h);
  if (n - h < 2)
    return false;
  /* lines[k]: piece k's lines, its room (one slot a line); first[k]: where
   * the room starts, after the header's shapes (not its lines) */
  int lines[PARTS_PIECES_MAX + 2], first[PARTS_PIECES_MAX + 2];
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < n; k++)
    lines[k] = count_lines(text + start[k], start[k + 1] - start[k]);
  int total = 0;
  for (int k = 0; k < n; k++)
    total += lines[k];
  Instance *shapes = shapes_array(total);
  ParserPart *part[PARTS_PIECES_MAX + 2] = {NULL};
  if (!shapes)
    return false;
  first[0] = 0;
  if (h)
    part[0] = parser_part_parse(file, text, 0, start[1], NULL, shapes, lines[0]);
  first[h] = h && part[0] ? parser_part_shapes(part[0]) : 0;
  for (int k = h; k < n; k++)
    first[k + 1] = first[k] + lines[k];
  /* A piece that fails (an error: the one-pass parse will say which) stops
   * the pieces not started yet. */
  int failed = h && !part[0];
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = h; k < n; k++) {
    int stop;
#pragma omp atomic read
    stop = failed;
    if (stop)
      continue;
    part[k] = parser_part_parse(file, text, start[k], start[k + 1], h ? part[0] : NULL,
                                shapes + first[k], lines[k]);
    if (!part[k]) {
#pragma omp atomic write
      failed = 1;
    }
  }
  bool ok = !failed;
  ok = ok && parser_parts_join(part, n, shapes, scene);
  for (int k = 0; k < n; k++)
    parser_part_free(part[k]);
  if (!ok)
    free(shapes);
  return ok;
}

bool parts_parse(const char *file, const char *text, size_t len, Scene *scene)
{
  size_t pieces = len / PARTS_PIECE_MIN, threads = (size_t)omp_get_max_threads();
  if (pieces < 2 || threads < 2)
    return false;
  size_t want = PIECES_PER_THREAD * threads;
  return parts_load(file, text, len, scene, (int)(pieces < want ? pieces : want));
}
