/* Whole scene texts (step 02): a file read whole, then parsed; a large text
 * in pieces at once, four per thread taken in turn, each writing its shapes
 * at its place in one array, merged in file order (a scene of 10^6 spheres
 * is 74 MB). The lines before the first sphere line, when they are short,
 * are parsed first and their materials given to every piece. Errors are
 * always reported by the one-piece parse, so they read the same.
 * docs/scene-format.md; docs/reliability.md. */
#define _GNU_SOURCE /* memmem */
#include "app/parser.h"
#include "app/parser_state.h"

#include <errno.h>
#include "threads.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/textfile.h"
#include "grow.h"
#include "pages.h"

enum {
  PIECE_MIN = 1 << 21, /* bytes: smaller texts are parsed in one piece */
  PIECES_MAX = 64,
  PIECES_PER_THREAD = 4, /* taken in turn: a slow core holds up less */
};

static bool parse_whole(const char *file, const char *text, size_t len, Scene *scene)
{
  Parser p;
  parser_begin(&p, file, text, len, scene);
  lexer_skip_bom(&p.lx);
  bool ok = parser_statements(&p) && parser_resolve(&p);
  parser_end(&p);
  if (!ok)
    scene_free(scene);
  return ok;
}

/* Piece boundaries in text[from .. len), each just after a '\n':
 * start[0 .. n], start[0] = from, start[n] = len. The pieces shrink as the
 * parse goes on (piece k of `want` about (2 (want - k) - 1) / want^2 of the
 * text), so that the threads, taking them in turn, finish close together: a
 * thread the machine slows down holds the others up by at most one small
 * piece. With pieces of one size, one thread of two waited a median 7.7 ms
 * (up to 18.6 ms) for the other at the end of the 10^6-sphere parse, now
 * 2.2 ms (up to 6.5 ms; docs/reliability.md, "Thirteenth pass"). */
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

typedef struct Piece {
  Scene scene;
  Parser p;
  bool ok;
} Piece;

/* The header: the lines before the first that starts with a sphere, when it
 * starts within the first `limit` bytes; 0 otherwise. Parsed alone first, it
 * gives its materials to every piece, which then finds the materials the
 * spheres name instead of keeping each reference to resolve later (10^6
 * spheres: 500 000 references, 8 MB, in the second of two pieces;
 * docs/reliability.md, "Sixth pass"). */
static size_t header_length(const char *text, size_t len, size_t limit)
{
  static const char word[] = "\nsphere ";
  if (len < limit)
    limit = len;
  const char *at = memmem(text, limit, word, sizeof word - 1);
  return at ? (size_t)(at - text) + 1 : 0;
}

/* Piece `to` starts out knowing the materials of the header `h` (the first
 * of its own materials, then, is h's count). False when out of memory. */
static bool preload_materials(Piece *to, const Piece *h)
{
  Scene *s = &to->scene;
  for (int k = 0; k < h->scene.n_materials; k++)
    if (!scene_add_material(s, &h->scene.materials[k]) ||
        !names_add(&to->p.names, parser_materials(s), k))
      return false;
  return true;
}

/* The values of piece q's once-statements into piece 0's; false when both
 * have one (the whole parse says where the second is). */
static bool merge_once(Piece *to, const Piece *q)
{
  for (int w = 0; w < ONCE_COUNT; w++) {
    if (!q->p.once_line[w])
      continue;
    if (to->p.once_line[w])
      return false;
    to->p.once_line[w] = 1;
    const Scene *s = &q->scene;
    switch (w) {
    case ONCE_FILM: to->scene.width = s->width, to->scene.height = s->height; break;
    case ONCE_CAMERA: to->scene.camera = s->camera; break;
    case ONCE_AMBIENT: to->scene.ambient = s->ambient; break;
    case ONCE_BACKGROUND: to->scene.background = s->background; break;
    case ONCE_SAMPLES: to->scene.samples = s->samples; break;
    default: to->scene.light_samples = s->light_samples; break;
    }
  }
  return true;
}

/* Piece q's shapes, parsed in place further on in the array piece 0's scene
 * owns, moved down to follow piece 0's; the indices of the materials q
 * defined itself (after the `known` ones it was given, which keep theirs)
 * moved to where they land, from first_material on. */
static void merge_shapes(Scene *s, const Scene *q, int known, int first_material)
{
  Instance *to = s->instances + s->n_instances;
  int n = q->n_instances, shift = first_material - known;
  if (to != q->instances) /* nothing to move after a header or shapes only */
    memmove(to, q->instances, (size_t)n * sizeof *to);
  /* A piece that defines no material has no index to move: its shapes'
   * materials are the given ones or references resolved by the pending
   * merge (a light's shape has none, -1). */
  if (q->n_materials > known) {
#pragma omp parallel for schedule(static) if (n > 65536)
    for (int k = 0; k < n; k++)
      to[k].material += to[k].material >= known ? shift : 0;
  }
  if (q->n_shapes > 0)
    s->n_shapes = s->n_instances + q->n_shapes;
  s->n_instances += q->n_instances;
}

/* Piece q's planes, which its shapes point to, handed to s; false when out
 * of memory (each piece then still owns its own). */
static bool take_planes(Scene *s, Scene *q)
{
  if (q->n_planes == 0)
    return true;
  if (!grow_reserve((void **)&s->planes, (size_t)s->n_planes, (size_t)q->n_planes,
                    sizeof *s->planes))
    return false;
  memcpy(s->planes + s->n_planes, q->planes, (size_t)q->n_planes * sizeof *q->planes);
  s->n_planes += q->n_planes;
  q->n_planes = 0;
  return true;
}

/* Append piece q to piece 0: materials (each name new; q's first `known`
 * were piece 0's to begin with), lights, planes, shapes (their material
 * indices moved past piece 0's), references to materials not defined in q before
 * them (resolved when piece 0 now has the material, else left to resolve).
 * False on a conflict or out of memory. */
static bool merge(Piece *to, Piece *q, int known)
{
  Scene *s = &to->scene;
  int first_material = s->n_materials, first_instance = s->n_instances;
  if (!merge_once(to, q))
    return false;
  for (int k = known; k < q->scene.n_materials; k++) {
    const Material *m = &q->scene.materials[k];
    if (names_find(&to->p.names, parser_materials(s), m->name, (int)strlen(m->name)) >= 0 ||
        !scene_add_material(s, m) || !names_add(&to->p.names, parser_materials(s),
                                                s->n_materials - 1))
      return false;
  }
  for (int k = 0; k < q->scene.n_lights; k++)
    if (!scene_add_light(s, &q->scene.lights[k]))
      return false;
  if (!take_planes(s, &q->scene))
    return false;
  merge_shapes(s, &q->scene, known, first_material);
  return parser_pending_merge(&to->p, &q->p, first_instance);
}

/* Lines in text[0 .. len): its newlines, plus one for a last line without
 * one. Counted 255 bytes at a time in one byte, which the compiler turns
 * into vector compares (12 GB/s here, a third of the time of a count in
 * size_t). */
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

int parser_reparses = 0;
int parser_pieces_pending = 0;

/* Piece k of the text, starting at its place `shapes` in the shared array,
 * with room for `room` shapes. */
static void piece_begin(Piece *pc, const char *file, const char *text, size_t len,
                        Instance *shapes, int room, bool first)
{
  scene_init(&pc->scene);
  pc->scene.instances = shapes;
  parser_begin(&pc->p, file, text, len, &pc->scene);
  pc->p.room = room;
  pc->p.lx.quiet = true;
  if (first)
    lexer_skip_bom(&pc->p.lx);
}

bool parser_load_chunks(const char *file, const char *text, size_t len, Scene *scene,
                        int chunks)
{
  if (chunks < 2)
    return parse_whole(file, text, len, scene);
  int want = chunks < PIECES_MAX ? chunks : PIECES_MAX;
  /* A header of at most a sixteenth of a piece's mean share (parsed alone,
   * while the other threads wait) becomes piece 0: h = 1. */
  size_t start[PIECES_MAX + 2];
  size_t head = header_length(text, len, len / ((size_t)want * 16));
  int h = head > 0;
  start[0] = 0;
  int n = h + cut_pieces(text, head, len, want, start + h);
  /* aligned: a Scene holds cglm matrices, 32-byte aligned in AVX builds */
  Piece *piece = aligned_alloc(_Alignof(Piece), (size_t)n * sizeof *piece);
  if (n - h < 2 || !piece) {
    free(piece);
    return parse_whole(file, text, len, scene);
  }
  /* One array for every piece's shapes, room for one a line (a statement
   * is a line): piece k parses into it from first[k], so merging moves each
   * piece down over the few lines that were not shapes instead of copying
   * it into new memory (docs/reliability.md, "Fifth pass"). The header is
   * parsed first, into an array of its own, and takes the room of its
   * shapes only: the pieces after a header and before any other line that
   * is not a shape stay where they are. The array's room is the growing
   * array's for that many (common/grow.h), as scene_free and later
   * additions expect. */
  int first[PIECES_MAX + 2];
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = h; k < n; k++)
    first[k + 1] = count_lines(text + start[k], start[k + 1] - start[k]);
  bool ok = true;
  if (h) {
    piece_begin(&piece[0], file, text, start[1], NULL, 0, true);
    ok = piece[0].ok = parser_statements(&piece[0].p);
    first[1] = piece[0].scene.n_instances;
  }
  first[0] = 0;
  for (int k = 0; k < n; k++)
    first[k + 1] += first[k];
  Instance *shapes = ok ? aligned_alloc(INSTANCE_ALIGN, grow_capacity((size_t)first[n]) *
                                                          sizeof *shapes)
                        : NULL;
  if (!shapes) {
    if (h) {
      parser_end(&piece[0].p);
      scene_free(&piece[0].scene);
    }
    free(piece);
    if (!ok) {
#pragma omp atomic
      parser_reparses++;
    }
    return parse_whole(file, text, len, scene);
  }
  if (h) { /* the header's shapes to the front of the shared array */
    if (first[1] > 0)
      memcpy(shapes, piece[0].scene.instances, (size_t)first[1] * sizeof *shapes);
    free(piece[0].scene.instances);
    piece[0].scene.instances = shapes;
  }
  int known = h ? piece[0].scene.n_materials : 0; /* what each piece is given */
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = h; k < n; k++) {
    pages_populate(shapes + first[k], (size_t)(first[k + 1] - first[k]) * sizeof *shapes);
    piece_begin(&piece[k], file, text + start[k], start[k + 1] - start[k], shapes + first[k],
                first[k + 1] - first[k], k == 0);
    piece[k].ok = (!h || preload_materials(&piece[k], &piece[0])) &&
                  parser_statements(&piece[k].p);
#pragma omp atomic
    parser_pieces_pending += piece[k].p.n_pending;
  }
  for (int k = 0; k < n; k++)
    ok = ok && piece[k].ok && (k == 0 || merge(&piece[0], &piece[k], known));
  ok = ok && parser_resolve(&piece[0].p);
  for (int k = 0; k < n; k++) {
    parser_end(&piece[k].p);
    if (k > 0 || !ok) {
      piece[k].scene.instances = NULL; /* the shared array, freed once below */
      scene_free(&piece[k].scene);
    }
  }
  if (ok)
    *scene = piece[0].scene;
  else
    free(shapes);
  free(piece);
  if (ok)
    return true;
#pragma omp atomic
  parser_reparses++;
  return parse_whole(file, text, len, scene);
}

bool parser_load_text(const char *file, const char *text, size_t len, Scene *scene)
{
  if (len > PARSER_MAX_BYTES) {
    fprintf(stderr, "%s: expected at most %zu bytes, found %zu\n", file,
            PARSER_MAX_BYTES, len);
    scene_free(scene);
    return false;
  }
  size_t pieces = len / PIECE_MIN, threads = (size_t)omp_get_max_threads();
  if (pieces < 2 || threads < 2)
    return parse_whole(file, text, len, scene);
  size_t want = PIECES_PER_THREAD * threads;
  return parser_load_chunks(file, text, len, scene, (int)(pieces < want ? pieces : want));
}

bool parser_load_string(const char *file, const char *text, Scene *scene)
{
  return parser_load_text(file, text, strlen(text), scene);
}

bool parser_load_file(const char *path, Scene *scene)
{
  TextFile f;
  int err = textfile_read(path, PARSER_MAX_BYTES, &f);
  if (err == EFBIG)
    fprintf(stderr, "parser: cannot read '%s': larger than %zu bytes, the limit of a "
            "scene file\n", path, PARSER_MAX_BYTES);
  else if (err)
    fprintf(stderr, "parser: cannot read '%s': %s\n", path, strerror(err));
  if (err) {
    scene_free(scene);
    return false;
  }
  bool ok = parser_load_text(path, f.text, f.len, scene);
  textfile_free(&f);
  return ok;
}
