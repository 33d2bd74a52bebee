/* The `light` statement of the scene format (step 04 on; area lights step
 * 08): `light point|directional|area` and its keyword list.
 * docs/scene-format.md, "Statements". */
#include "app/light_statement.h"

#include <stdio.h>
#include <string.h>

#include "app/limits.h"

static bool light_point(Lexer *lx, Light *light)
{
  static const Key keys[] = {{"position", KEY_POINT, true}, {"power", KEY_POWER, true},
                             {"radius", KEY_NUM, false}};
  Field f[3];
  if (!fields_read(lx, "point light", keys, 3, f) ||
      (f[2].set && !limits_length(lx, &f[2], "radius")))
    return false;
  *light = (Light){.type = LIGHT_POINT, .position = f[0].v, .power = f[1].v,
                   .radius = f[2].v.x};
  return true;
}

static bool light_directional(Lexer *lx, Light *light)
{
  static const Key keys[] = {{"direction", KEY_VEC, true}, {"irradiance", KEY_COLOR, true}};
  Field f[2];
  if (!fields_read(lx, "directional light", keys, 2, f) ||
      !limits_direction(lx, &f[0], "direction"))
    return false;
  *light = (Light){.type = LIGHT_DIRECTIONAL, .direction = glms_vec3_normalize(f[0].v),
                   .irradiance = f[1].v};
  return true;
}

static bool light_area(Lexer *lx, Light *light)
{
  static const Key keys[] = {{"corner", KEY_POINT, true}, {"edge1", KEY_POINT, true},
                             {"edge2", KEY_POINT, true}, {"power", KEY_POWER, true}};
  Field f[4];
  if (!fields_read(lx, "area light", keys, 4, f) ||
      !limits_edges(lx, &f[1], &f[2]))
    return false;
  *light = (Light){.type = LIGHT_AREA, .quad = quad_make(f[0].v, f[1].v, f[2].v),
                   .power = f[3].v};
  return true;
}

/* The light types by their word, in the order messages list them
 * (docs/scene-format.md, "Statements"). */
static const struct LightKind {
  const char *word;
  bool (*read)(Lexer *lx, Light *light);
} KINDS[] = {{"point", light_point}, {"directional", light_directional}, {"area", light_area}};
enum { KIND_COUNT = sizeof KINDS / sizeof *KINDS };

bool light_statement(Lexer *lx, Light *light)
{
  const char *words[KIND_COUNT];
  for (int k = 0; k < KIND_COUNT; k++) {
    if (lexer_peek_is(lx, KINDS[k].word)) {
      lx->pos++;
      return KINDS[k].read(lx, light);
    }
    words[k] = KINDS[k].word;
  }
  if (lx->pos < lx->n)
    return lexer_fail_unknown(lx, "a light type", words, KIND_COUNT);
  char list[96] = "";
  for (int k = 0; k < KIND_COUNT; k++)
    snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", k ? ", " : "", words[k]);
  return lexer_fail(lx, lx->end_col, "expected a light type (%s), found end of line", list);
}
