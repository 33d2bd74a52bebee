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
  uint32_t tile; /* tiles started, from 1: entry.tile 0 is never current */
  MemoEntry e[MEMO_SIZE];
};

struct RenderMemo *render_memo_new(void)
{
  struct RenderMemo *memo = calloc(1, sizeof *memo);
  if (memo)
    memo->tile = 1;
  return memo;
}

void render_memo_next_tile(struct RenderMemo *memo)
{
  if (memo)
    memo->tile++;
}

vec3s render_point(const Scene *scene, const Film *film, RenderPointFn colour, uint32_t x,
                   uint32_t y)
{
  struct RenderMemo *memo = film->memo;
  MemoEntry none = {0}, *m = &none; /* no memo: compute every time */
  uint32_t h = (x * 0x9e3779b1u) ^ (y * 0x85ebca77u);
  if (memo)
    m = &memo->e[(h ^ (h >> 15)) & (MEMO_SIZE - 1)];
  if (memo && m->tile == memo->tile && m->x == x && m->y == y)
    return m->c;
  /* x / 256 is exact in float: x < 2^24 for any film side up to 65535. */
  vec3s c = colour(scene, (float)x / (float)RENDER_LATTICE, (float)y / (float)RENDER_LATTICE);
  if (memo)
    *m = (MemoEntry){.x = x, .y = y, .tile = memo->tile, .c = c};
  return c;
}
