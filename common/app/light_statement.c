/* The `light` statement of the scene format (step 04 on; area lights step
 * 08): `light point|directional|area` and its keyword list.
 * docs/scene-format.md, "Statements". */
#include "app/light_statement.h"

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

bool light_statement(Lexer *lx, Light *light)
{
  static const char *const types[] = {"point", "directional", "area"};
  int k = 0;
  while (k < 3 && !lexer_peek_is(lx, types[k]))
    k++;
  if (k == 3 && lx->pos < lx->n)
    return lexer_fail_unknown(lx, "a light type", types, 3);
  if (k == 3)
    return lexer_fail(lx, lx->end_col, "expected a light type (point, directional, "
                      "area), found end of line");
  lx->pos++;
  return k == 0 ? light_point(lx, light)
         : k == 1 ? light_directional(lx, light) : light_area(lx, light);
}

