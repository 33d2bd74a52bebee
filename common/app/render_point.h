/* Adaptive sampling's lattice points (step 07): the colour at a point of a
 * fine lattice over the film, computed once per tile and remembered, so that
 * a pixel corner is shaded once for the four pixels around it.
 * docs/07-antialiasing.md, "Adaptive sampling". */
#ifndef RT_RENDER_POINT_H
#define RT_RENDER_POINT_H

#include "app/render.h"

/* Adaptive sampling (step 07) places its samples on a lattice of
 * RENDER_LATTICE x RENDER_LATTICE points per pixel: lattice point (x, y) is
 * the film point (x, y) / RENDER_LATTICE pixels from the film's bottom-left
 * corner; pixel (i, j)'s corners are (i, j) * RENDER_LATTICE and the next
 * ones along. */
enum { RENDER_LATTICE = 256 };

/* A step's camera sample: the colour seen through the film point (x, y),
 * in pixels from the film's bottom-left corner (x in [0, width]). */
typedef vec3s (*RenderPointFn)(const Scene *scene, float x, float y, RenderCtx *ctx);

/* The colour at lattice point (x, y), computed by `colour` the first time
 * the current tile asks for it and remembered for the rest of the tile (a
 * pixel corner serves the four pixels around it, a point on an edge the two
 * on either side). While `colour` runs, ctx->pixel and ctx->sample name the
 * point, not the pixel that asked: ctx->pixel = the corner (x, y) /
 * RENDER_LATTICE rounded down, as j * (width + 1) + i, and ctx->sample = its
 * place above that corner, (y % RENDER_LATTICE) * RENDER_LATTICE +
 * x % RENDER_LATTICE; both are restored afterwards. So a point's colour is a
 * function of its place alone, whichever pixel or thread asks first. */
vec3s render_point(const Scene *scene, RenderCtx *ctx, RenderPointFn colour, uint32_t x,
                   uint32_t y);

#endif
