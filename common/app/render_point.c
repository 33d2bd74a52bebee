/* Adaptive sampling's lattice points (step 07; common/app/render_point.h):
 * render_point remembers the colours a tile has computed, so that a pixel
 * corner is shaded once for the four pixels around it.
 * docs/07-antialiasing.md, "Adaptive sampling". */
#include "app/render_point.h"

#include <stdlib.h>

/* render_point's memo: a direct-mapped table of lattice points, an entry
 * valid only while its tile is the thread's current one. A tile asks for
 * about (TILE + 1)^2 corners and a few hundred points inside pixels; a
 * collision only computes a point again (the same colour), so the table need
 * not hold them all. */
enum { MEMO_BITS = 12, MEMO_SIZE = 1 << MEMO_BITS };

typedef struct MemoEntry {
  uint32_t x, y, tile;
  vec3s c;
} MemoEntry;

struct RenderMemo {
  MemoEntry e[MEMO_SIZE];
};

vec3s render_point(const Scene *scene, RenderCtx *ctx, RenderPointFn colour, uint32_t x,
                   uint32_t y)
{
  if (!ctx->memo)
    ctx->memo = calloc(1, sizeof *ctx->memo);
  MemoEntry none, *m = &none; /* no memory for a memo: compute every time */
  uint32_t h = (x * 0x9e3779b1u) ^ (y * 0x85ebca77u);
  if (ctx->memo)
    m = &ctx->memo->e[(h ^ (h >> 15)) & (MEMO_SIZE - 1)];
  else
    none.tile = ctx->tile - 1u;
  if (m->tile == ctx->tile && m->x == x && m->y == y)
    return m->c;
  uint32_t pixel = ctx->pixel, sample = ctx->sample;
  uint32_t i = x / RENDER_LATTICE, j = y / RENDER_LATTICE;
  ctx->pixel = j * ((uint32_t)scene->width + 1u) + i;
  ctx->sample = (y % RENDER_LATTICE) * RENDER_LATTICE + x % RENDER_LATTICE;
  /* x / 256 is exact in float: x < 2^24 for any film side up to 65535. */
  vec3s c = colour(scene, (float)x / (float)RENDER_LATTICE, (float)y / (float)RENDER_LATTICE,
                  ctx);
  ctx->pixel = pixel;
  ctx->sample = sample;
  *m = (MemoEntry){.x = x, .y = y, .tile = ctx->tile, .c = c};
  return c;
}

