/* Keyword lists of the scene format: `keyword values` pairs to the end of a
 * statement's line, in any order, each keyword at most once (`sphere center
 * 0 1 0 radius 1 material red`). Introduced in step 02; docs/scene-format.md. */
#ifndef RT_FIELDS_H
#define RT_FIELDS_H

#include <math.h>

#include "app/lexer.h"

typedef enum KeyKind {
  KEY_POINT,  /* three coordinates, each at most LEXER_MAX_COORD in magnitude */
  KEY_VEC,    /* three numbers (a direction: the statement checks its length) */
  KEY_COLOR,  /* three numbers from 0 to LEXER_MAX_COLOR */
  KEY_POWER,  /* three numbers from 0 to LEXER_MAX_POWER (a light's power) */
  KEY_NUM,    /* one number */
  KEY_NAME,   /* a material name */
} KeyKind;

typedef struct Key {
  const char *name;
  KeyKind kind;
  bool required;
} Key;

typedef struct Field {
  bool set;
  int col;     /* column of the keyword */
  int val;     /* lx->tok index of its first value (valid for this line) */
  int val_col; /* column of its first value (end of line when it has none) */
  vec3s v;     /* the vector, or v.x for KEY_NUM */
} Field;

enum { FIELDS_MAX = 6 };

/* A coordinate a KEY_POINT may hold: |v| <= LEXER_MAX_COORD (not NaN). */
static inline bool fields_coordinate_ok(float v)
{
  return fabsf(v) <= LEXER_MAX_COORD;
}

/* Read the rest of the line as keyword lists of `keys` into `fields` (same
 * order); each keyword at most once, required ones present. `what` names the
 * statement in messages ("sphere"). Prints one line and returns false on
 * error. */
bool fields_read(Lexer *lx, const char *what, const Key *keys, int n_keys, Field *fields);

/* The field's first `words` values as written, separated by spaces ("1 0 0"),
 * into `buf` (truncated to `size`); returns buf. */
const char *fields_text(const Lexer *lx, const Field *f, int words, char *buf, size_t size);

#endif
