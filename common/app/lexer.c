/* Scene-file lexer: a line's words with their columns, and readers for the
 * values statements take (numbers, vectors, names, keyword lists). Every error
 * is one line FILE:LINE:COL. Introduced in step 02; docs/scene-format.md. */
#include "app/lexer.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Print `FILE:LINE:COL: message` and return false. */
bool lexer_fail(const Lexer *lx, int col, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "%s:%d:%d: ", lx->file, lx->line, col);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  return false;
}

/* What the next token is, for messages: 'text' or "end of line". */
static const char *found(const Lexer *lx, char *buf, size_t size)
{
  if (lx->pos >= lx->n)
    return "end of line";
  const Token *t = &lx->tok[lx->pos];
  snprintf(buf, size, "'%.*s'", t->len > 40 ? 40 : t->len, t->s);
  return buf;
}

/* The token's text into out (truncated to size - 1 bytes), as snprintf's
 * "%.*s" would write it: a scene of 10^6 spheres has 10^7 tokens, and
 * snprintf's formatting machinery cost a third of its parse time. */
static void tok_copy(char *out, size_t size, const Token *t)
{
  size_t n = (size_t)t->len < size - 1 ? (size_t)t->len : size - 1;
  memcpy(out, t->s, n);
  out[n] = '\0';
}

/* Append s to the string in out, truncated as snprintf would. */
static void append(char *out, size_t size, const char *s)
{
  size_t n = strlen(out);
  while (*s && n + 1 < size)
    out[n++] = *s++;
  out[n] = '\0';
}

static int next_col(const Lexer *lx)
{
  return lx->pos < lx->n ? lx->tok[lx->pos].col : lx->end_col;
}

static bool tok_is(const Token *t, const char *word)
{
  return (int)strlen(word) == t->len && strncmp(t->s, word, (size_t)t->len) == 0;
}

void lexer_init(Lexer *lx, const char *file, const char *text)
{
  memset(lx, 0, sizeof *lx);
  lx->file = file;
  lx->next = text;
}

int lexer_line(Lexer *lx)
{
  while (*lx->next) {
    const char *s = lx->next;
    lx->line++;
    lx->n = lx->pos = 0;
    bool comment = false;
    int col = 1;
    for (; *s && *s != '\n'; s++, col++) {
      unsigned char c = (unsigned char)*s;
      bool space = c == ' ' || c == '\t' || c == '\r';
      if (c == '#')
        comment = true;
      if (comment)
        continue;
      if (!space && (c < 32 || c == 127))
        return lexer_fail(lx, col, "expected text, found the control byte 0x%02x", c) - 1;
      bool starts = !space && (col == 1 || s[-1] == ' ' || s[-1] == '\t' || s[-1] == '\r');
      if (starts) {
        if (lx->n == LEXER_MAX_TOKENS)
          return lexer_fail(lx, col, "expected at most %d words on a line, found more",
                            LEXER_MAX_TOKENS) - 1;
        lx->tok[lx->n++] = (Token){s, 0, col};
      }
      if (!space) {
        Token *t = &lx->tok[lx->n - 1];
        if (++t->len == LEXER_TOKEN_MAX)
          return lexer_fail(lx, t->col, "expected a word of at most %d characters, "
                            "found a longer one", LEXER_TOKEN_MAX - 1) - 1;
        lx->end_col = col + 1;
      }
    }
    lx->next = *s ? s + 1 : s;
    if (lx->n > 0)
      return 1;
  }
  return 0;
}

bool lexer_peek_is(const Lexer *lx, const char *word)
{
  return lx->pos < lx->n && tok_is(&lx->tok[lx->pos], word);
}

/* Levenshtein distance, for "did you mean" (words are short). */
static int edit_distance(const char *a, int la, const char *b)
{
  int lb = (int)strlen(b), row[LEXER_TOKEN_MAX + 1];
  if (la > LEXER_TOKEN_MAX || lb > LEXER_TOKEN_MAX)
    return LEXER_TOKEN_MAX;
  for (int j = 0; j <= lb; j++)
    row[j] = j;
  for (int i = 1; i <= la; i++) {
    int diag = row[0];
    row[0] = i;
    for (int j = 1; j <= lb; j++) {
      int up = row[j];
      int sub = diag + (a[i - 1] != b[j - 1]);
      row[j] = sub < up + 1 ? sub : up + 1;
      if (row[j - 1] + 1 < row[j])
        row[j] = row[j - 1] + 1;
      diag = up;
    }
  }
  return row[lb];
}

/* Fail on an unknown word, listing the valid ones and the nearest of them. */
bool lexer_fail_unknown(const Lexer *lx, const char *what,
                         const char *const *words, int n_words)
{
  char buf[64], list[256] = "", hint[96] = "";
  int best = LEXER_TOKEN_MAX;
  const Token *t = &lx->tok[lx->pos];
  for (int k = 0; k < n_words; k++) {
    snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s",
             k ? ", " : "", words[k]);
    int d = edit_distance(t->s, t->len, words[k]);
    if (d < best && d <= 2 && d < (int)strlen(words[k])) {
      best = d;
      snprintf(hint, sizeof hint, "; did you mean '%s'?", words[k]);
    }
  }
  return lexer_fail(lx, t->col, "expected %s (%s), found %s%s", what, list,
              found(lx, buf, sizeof buf), hint);
}

/* Read a finite number; `nonneg` also rejects negative values (then `what`
 * says ">= 0"). An underflow to 0 or a subnormal is accepted (strtof's
 * ERANGE): only overflow is non-finite. */
bool lexer_number(Lexer *lx, const char *what, bool nonneg, float *out)
{
  char buf[64], text[LEXER_TOKEN_MAX];
  if (lx->pos >= lx->n)
    return lexer_fail(lx, lx->end_col, "expected %s, found end of line", what);
  const Token *t = &lx->tok[lx->pos];
  tok_copy(text, sizeof text, t);
  char *end;
  float v = strtof(text, &end);
  if (end == text || *end != '\0')
    return lexer_fail(lx, t->col, "expected %s, found %s", what, found(lx, buf, sizeof buf));
  if (!isfinite(v))
    return lexer_fail(lx, t->col, "expected %s, found a non-finite value %s", what,
                found(lx, buf, sizeof buf));
  if (nonneg && v < 0.0f)
    return lexer_fail(lx, t->col, "expected %s, found %s", what, found(lx, buf, sizeof buf));
  lx->pos++;
  *out = v;
  return true;
}

bool lexer_vec(Lexer *lx, const char *what, bool nonneg, vec3s *out)
{
  for (int k = 0; k < 3; k++)
    if (!lexer_number(lx, what, nonneg, &out->raw[k]))
      return false;
  return true;
}

/* A whole number in [lo, hi]. */
bool lexer_int(Lexer *lx, const char *what, int lo, int hi, int *out)
{
  char buf[64];
  int col = next_col(lx);
  float v = 0.0f;
  if (!lexer_number(lx, what, false, &v))
    return false;
  lx->pos--;
  if (v != floorf(v) || v < (float)lo || v > (float)hi)
    return lexer_fail(lx, col, "expected %s, a whole number from %d to %d, found %s",
                what, lo, hi, found(lx, buf, sizeof buf));
  lx->pos++;
  *out = (int)v;
  return true;
}

bool lexer_name(Lexer *lx, const char *what, char out[MATERIAL_NAME_MAX])
{
  char buf[64];
  if (lx->pos >= lx->n)
    return lexer_fail(lx, lx->end_col, "expected %s, found end of line", what);
  const Token *t = &lx->tok[lx->pos];
  bool ok = t->len < MATERIAL_NAME_MAX && (t->s[0] == '_' || (t->s[0] | 32) >= 'a')
            && (t->s[0] | 32) <= 'z';
  for (int k = 1; ok && k < t->len; k++)
    ok = t->s[k] == '_' || (t->s[k] >= '0' && t->s[k] <= '9') ||
         ((t->s[k] | 32) >= 'a' && (t->s[k] | 32) <= 'z');
  if (!ok)
    return lexer_fail(lx, t->col, "expected %s (letters, digits, '_', at most %d "
                "characters), found %s", what, MATERIAL_NAME_MAX - 1,
                found(lx, buf, sizeof buf));
  tok_copy(out, MATERIAL_NAME_MAX, t);
  lx->pos++;
  return true;
}

bool lexer_expect_end(Lexer *lx)
{
  char buf[64];
  if (lx->pos < lx->n)
    return lexer_fail(lx, lx->tok[lx->pos].col, "expected end of line, found an extra "
                "value %s", found(lx, buf, sizeof buf));
  return true;
}

/* ------------------------------------------------------------ keyword lists */

/* Read `keyword values` pairs to the end of the line, in any order. */
bool lexer_fields(Lexer *lx, const char *what, const Key *keys, int n_keys,
                        Field *fields)
{
  const char *names[LEXER_MAX_KEYS];
  for (int k = 0; k < n_keys; k++)
    names[k] = keys[k].name;
  memset(fields, 0, sizeof(Field) * (size_t)n_keys);
  while (lx->pos < lx->n) {
    const Token *t = &lx->tok[lx->pos];
    int k = 0;
    while (k < n_keys && !tok_is(t, keys[k].name))
      k++;
    if (k == n_keys) {
      char *end;
      char text[LEXER_TOKEN_MAX];
      tok_copy(text, sizeof text, t);
      strtof(text, &end);
      if (end != text && *end == '\0')
        return lexer_fail(lx, t->col, "expected a %s keyword, found an extra value '%s'",
                    what, text);
      char kw[96];
      snprintf(kw, sizeof kw, "a %s keyword", what);
      return lexer_fail_unknown(lx, kw, names, n_keys);
    }
    if (fields[k].set)
      return lexer_fail(lx, t->col, "expected each %s keyword once, found a second "
                  "'%s' (first at column %d)", what, keys[k].name, fields[k].col);
    fields[k].set = true;
    fields[k].col = t->col;
    lx->pos++;
    fields[k].val_col = next_col(lx);
    if (lx->pos < lx->n)
      tok_copy(fields[k].text, sizeof fields[k].text, &lx->tok[lx->pos]);
    KeyKind kind = keys[k].kind;
    char desc[96] = ""; /* what the values are, for messages: "3 numbers after 'center'" */
    append(desc, sizeof desc, kind == KEY_NUM     ? "a number"
                              : kind == KEY_COLOR ? "3 numbers >= 0" : "3 numbers");
    append(desc, sizeof desc, " after '");
    append(desc, sizeof desc, keys[k].name);
    append(desc, sizeof desc, "'");
    bool ok = kind == KEY_NUM    ? lexer_number(lx, desc, false, &fields[k].v.x)
              : kind == KEY_NAME ? lexer_name(lx, "a material name", fields[k].name)
                                 : lexer_vec(lx, desc, kind == KEY_COLOR, &fields[k].v);
    if (!ok)
      return false;
  }
  for (int k = 0; k < n_keys; k++)
    if (keys[k].required && !fields[k].set)
      return lexer_fail(lx, lx->end_col, "expected '%s' in this %s statement, found end "
                  "of line", keys[k].name, what);
  return true;
}

