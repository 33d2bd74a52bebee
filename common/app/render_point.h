/* Adaptive sampling's lattice points (step 07): the colour at a point of a
 * fine lattice over the film, computed once per tile and remembered, so that
 * a pixel corner is shaded once for the four pixels around it.
 * docs/07-antialiasing.md, "Adaptive sampling". */
#ifndef RT_RENDER_POINT_H
#define RT_RENDER_POINT_H

#include <stdint.h>
#include "film.h"
#include "scene.h"

/* Adaptive sampling (step 07) places its samples on a lattice of
 * RENDER_LATTICE x RENDER_LATTICE points per pixel: lattice point (x, y) is
 * the film point (x, y) / RENDER_LATTICE pixels from the film's bottom-left
 * corner; pixel (i, j)'s corners are (i, j) * RENDER_LATTICE and the next
 * ones along. */
enum { RENDER_LATTICE = 256 };

/* A camera sample: the colour seen through the film point (x, y), in pixels
 * from the film's bottom-left corner (x in [0, width]). */
typedef vec3s (*RenderPointFn)(const Scene *scene, float x, float y);

/* The colour at lattice point (x, y), computed by `colour` the first time
 * the current tile asks for it and remembered in film->memo for the rest of
 * the tile (a pixel corner serves the four pixels around it, a point on an
 * edge the two on either side); computed every time when film->memo is
 * NULL. A point's colour is a function of its place alone. */
vec3s render_point(const Scene *scene, const Film *film, RenderPointFn colour, uint32_t x,
                   uint32_t y);

/* A memo for one thread (NULL when out of memory: render_point then
 * computes every point), free()d by its owner; render_memo_next_tile
 * forgets what the last tile computed, so that what a tile traces never
 * depends on the tiles the thread did before. */
struct RenderMemo *render_memo_new(void);
void render_memo_next_tile(struct RenderMemo *memo);

#endif
