/* The limits a scene's values must keep so that every float the renderer
 * derives from them stays finite and normal: directions that normalise,
 * lengths whose squares fit, areas that fit (a coordinate's limit is
 * fields_coordinate_ok, checked as a point is read). Each check prints the
 * parser's FILE:LINE:COL message and returns false. Introduced in step 02;
 * docs/scene-format.md, "Limits". */
#ifndef RT_LIMITS_H
#define RT_LIMITS_H

#include "app/fields.h"

/* A length the scene may hold: LEXER_MIN_LENGTH <= v <= LEXER_MAX_COORD. */
static inline bool limits_length_ok(float v)
{
  return v >= LEXER_MIN_LENGTH && v <= LEXER_MAX_COORD;
}

/* sin of the angle between a and b, computed in double. */
double limits_sin_angle(vec3s a, vec3s b);

/* A non-zero direction of length in [LEXER_MIN_LENGTH, LEXER_MAX_COORD]
 * (normal, up, light direction): its square is then a normal float. */
bool limits_direction(Lexer *lx, const Field *f, const char *what);

/* A length > 0 in [LEXER_MIN_LENGTH, LEXER_MAX_COORD] (a radius). */
bool limits_length(Lexer *lx, const Field *f, const char *what);

/* An area light's edges: non-zero, not parallel, and an area |e1 x e2|, as
 * quad_make computes it in float, in [LEXER_MIN_LENGTH, LEXER_MAX_COORD]. */
bool limits_edges(Lexer *lx, const Field *e1, const Field *e2);

#endif
