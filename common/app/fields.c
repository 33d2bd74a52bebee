/* Keyword lists of the scene format (step 02): `keyword values` pairs in any
 * order. docs/scene-format.md, "Statements". */
#include "app/fields.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "app/number.h"
#include "material.h"

/* Append s to the string in out, truncated as snprintf would. */
static void append(char *out, size_t size, const char *s)
{
  size_t n = strlen(out);
  while (*s && n + 1 < size)
    out[n++] = *s++;
  out[n] = '\0';
}

static int count_of(KeyKind kind)
{
  return kind == KEY_NUM ? 1 : kind == KEY_NAME ? 0 : 3;
}

/* The values of a key, read without building a message: true when every one
 * is a number of the kind (the common case). */
static bool values_fast(const Lexer *lx, KeyKind kind, vec3s *v)
{
  int n = count_of(kind);
  if (lx->pos + n > lx->n)
    return false;
  for (int k = 0; k < n; k++) {
    const Token *t = &lx->tok[lx->pos + k];
    if (number_parse(t->s, t->len, &v->raw[k]) != NUMBER_OK ||
        (kind == KEY_COLOR && !(v->raw[k] >= 0.0f && v->raw[k] <= LEXER_MAX_COLOR)) ||
        (kind == KEY_POWER && !(v->raw[k] >= 0.0f && v->raw[k] <= LEXER_MAX_POWER)) ||
        (kind == KEY_POINT && !fields_coordinate_ok(v->raw[k])))
      return false;
  }
  return true;
}

/* The same values read again with the messages: prints the first error. */
static bool values_slow(Lexer *lx, const Key *key, vec3s *v)
{
  char what[96] = "";
  bool nonneg = key->kind == KEY_COLOR || key->kind == KEY_POWER;
  append(what, sizeof what, key->kind == KEY_NUM ? "a number"
                            : nonneg             ? "3 numbers >= 0" : "3 numbers");
  append(what, sizeof what, " after '");
  append(what, sizeof what, key->name);
  append(what, sizeof what, "'");
  if (key->kind == KEY_NUM)
    return lexer_number(lx, what, false, &v->x);
  if (nonneg)
    return lexer_colour(lx, what, key->kind == KEY_POWER ? LEXER_MAX_POWER : LEXER_MAX_COLOR,
                        v);
  for (int k = 0; k < 3; k++) {
    int col = lx->pos < lx->n ? lx->tok[lx->pos].col : lx->end_col;
    if (!lexer_number(lx, what, false, &v->raw[k]))
      return false;
    if (key->kind == KEY_POINT && !fields_coordinate_ok(v->raw[k]))
      return lexer_fail(lx, col, "expected a coordinate from -1e18 to 1e18 after '%s' "
                        "(squares and differences must fit in a float), found '%.*s'",
                        key->name, lx->tok[lx->pos - 1].len, lx->tok[lx->pos - 1].s);
  }
  return true;
}

/* A word that is no keyword: an extra value when it reads as a number. */
static bool unknown(const Lexer *lx, const char *what, const Key *keys, int n_keys)
{
  const char *names[FIELDS_MAX];
  for (int k = 0; k < n_keys; k++)
    names[k] = keys[k].name;
  const Token *t = &lx->tok[lx->pos];
  float v;
  if (number_parse(t->s, t->len, &v) != NUMBER_BAD)
    return lexer_fail(lx, t->col, "expected a %s keyword, found an extra value '%.*s'",
                      what, t->len, t->s);
  char kw[96];
  snprintf(kw, sizeof kw, "a %s keyword", what);
  return lexer_fail_unknown(lx, kw, names, n_keys);
}

/* Read the values of key k into fields[k]. */
static bool field(Lexer *lx, const char *what, const Key *keys, int k, Field *fields)
{
  Field *f = &fields[k];
  if (f->set)
    return lexer_fail(lx, lx->tok[lx->pos].col, "expected each %s keyword once, found a "
                      "second '%s' (first at column %d)", what, keys[k].name, f->col);
  f->set = true;
  f->col = lx->tok[lx->pos].col;
  lx->pos++;
  f->val = lx->pos;
  f->val_col = lx->pos < lx->n ? lx->tok[lx->pos].col : lx->end_col;
  if (keys[k].kind == KEY_NAME) {
    Token name;
    return lexer_name(lx, "a material name", MATERIAL_NAME_MAX - 1, &name);
  }
  if (values_fast(lx, keys[k].kind, &f->v)) {
    lx->pos += count_of(keys[k].kind);
    return true;
  }
  return values_slow(lx, &keys[k], &f->v);
}

bool fields_read(Lexer *lx, const char *what, const Key *keys, int n_keys, Field *fields)
{
  for (int k = 0; k < n_keys; k++)
    fields[k] = (Field){.set = false, .v = {.x = 0.0f, .y = 0.0f, .z = 0.0f}};
  while (lx->pos < lx->n) {
    const Token *t = &lx->tok[lx->pos];
    int k = 0;
    while (k < n_keys && !lexer_is(t, keys[k].name))
      k++;
    if (k == n_keys)
      return unknown(lx, what, keys, n_keys);
    if (!field(lx, what, keys, k, fields))
      return false;
  }
  for (int k = 0; k < n_keys; k++)
    if (keys[k].required && !fields[k].set)
      return lexer_fail(lx, lx->end_col, "expected '%s' in this %s statement, found end "
                        "of line", keys[k].name, what);
  return true;
}

const char *fields_text(const Lexer *lx, const Field *f, int words, char *buf, size_t size)
{
  buf[0] = '\0';
  for (int k = 0; k < words && f->val + k < lx->n; k++) {
    const Token *t = &lx->tok[f->val + k];
    char word[LEXER_TOKEN_MAX + 2];
    snprintf(word, sizeof word, "%s%.*s", k ? " " : "", t->len, t->s);
    append(buf, size, word);
  }
  return buf;
}
