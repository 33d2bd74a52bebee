/* The limits of a scene's values (step 02): what keeps the renderer's floats
 * finite. docs/scene-format.md, "Limits". */
#include "app/limits.h"

#include <math.h>
#include <string.h>

#include "quad.h"

double limits_sin_angle(vec3s a, vec3s b)
{
  double cx = (double)a.y * b.z - (double)a.z * b.y;
  double cy = (double)a.z * b.x - (double)a.x * b.z;
  double cz = (double)a.x * b.y - (double)a.y * b.x;
  double la = (double)a.x * a.x + (double)a.y * a.y + (double)a.z * a.z;
  double lb = (double)b.x * b.x + (double)b.y * b.y + (double)b.z * b.z;
  return sqrt((cx * cx + cy * cy + cz * cz) / (la * lb));
}

bool limits_direction(Lexer *lx, const Field *f, const char *what)
{
  char text[3 * LEXER_TOKEN_MAX];
  if (vec_is_zero(f->v))
    return lexer_fail(lx, f->val_col, "expected a non-zero %s, found '0 0 0'", what);
  double len = sqrt((double)f->v.x * f->v.x + (double)f->v.y * f->v.y +
                    (double)f->v.z * f->v.z);
  if (len < LEXER_MIN_LENGTH || len > LEXER_MAX_COORD)
    return lexer_fail(lx, f->val_col, "expected %s %s of length 1e-18 to 1e18 (it is "
                      "normalised in float), found '%s'", strchr("aeiou", what[0]) ? "an" : "a",
                      what, fields_text(lx, f, 3, text, sizeof text));
  return true;
}

bool limits_length(Lexer *lx, const Field *f, const char *what)
{
  char text[LEXER_TOKEN_MAX];
  if (limits_length_ok(f->v.x))
    return true;
  fields_text(lx, f, 1, text, sizeof text);
  if (!(f->v.x > 0.0f))
    return lexer_fail(lx, f->val_col, "expected a %s > 0, found '%s'", what, text);
  return lexer_fail(lx, f->val_col, "expected a %s from 1e-18 to 1e18 (its square must "
                    "fit in a float), found '%s'", what, text);
}

bool limits_edges(Lexer *lx, const Field *e1, const Field *e2)
{
  if (vec_is_zero(e1->v) || vec_is_zero(e2->v))
    return lexer_fail(lx, (vec_is_zero(e1->v) ? e1 : e2)->val_col, "expected a non-zero "
                      "%s, found '0 0 0'", vec_is_zero(e1->v) ? "edge1" : "edge2");
  if (!(limits_sin_angle(e1->v, e2->v) > 1e-6))
    return lexer_fail(lx, e2->val_col, "expected edge2 not parallel to edge1 (a light "
                      "with an area), found parallel edges");
  Quad q = quad_make(glms_vec3_zero(), e1->v, e2->v);
  if (!(q.area >= LEXER_MIN_LENGTH && q.area <= LEXER_MAX_COORD))
    return lexer_fail(lx, e2->val_col, "expected edges whose area |edge1 x edge2| is "
                      "from 1e-18 to 1e18 (in float), found %g", (double)q.area);
  return true;
}
