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
#include "app/render.h"
#include "film.h"
#include "scene.h"

/* film_init's contract (film.h): a zeroed film of width x height pixels,
 * freed by film_free; its pixels where they cost least to write. */
bool pack_film_init(Film *film, int width, int height);

/* Build scene->index, which chooses the instances each query tests, or
 * leave it NULL: the queries then test every instance in order. Call after
 * scene_prepare. False (one line printed) when out of memory. */
bool pack_index(Scene *scene);

enum { PACK_VIEW_MAX = 8 };

/* A scene as one point's shadow rays toward one area light see it. */
typedef struct PackView {
  Scene scene;          /* what the point's light samples are shaded in */
  SceneIndex index;     /* scene.index when narrowed: `any` over ids only */
  const Scene *whole;   /* the scene viewed: its index answers `closest` */
  int n;
  int ids[PACK_VIEW_MAX];
} PackView;

/* Fill view->scene for the shadow rays ray_spawn(hit, l) toward the front
 * side of the area light q: the scene itself, or a copy whose shadow
 * queries test only the lit shapes that may stand between them (none at
 * all when none can); scene_occluded answers there exactly as on `scene`
 * for those rays. Returns how many of scene->light_samples the point takes. */
int pack_light_view(const Scene *scene, const Hit *hit, const Quad *q,
                    const RenderSettings *set, PackView *view);

/* Parse a large scene text as parser_load_text does (the same scene, the
 * same messages), faster: true when the pack took the text, *ok then the
 * verdict; false (nothing done) to leave it to parser_load_whole. */
bool pack_parse(const char *file, const char *text, size_t len, Scene *scene, bool *ok);

struct Parser;

/* Read the lines that follow in p's text itself where it can, faster than
 * parser_statements and as it would (the same shapes, any line of doubt
 * left to it); false when out of memory. */
bool pack_lines(struct Parser *p);

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
