/* Scene-file lexer: a line's words with their columns, and readers for the
 * values statements take (numbers, vectors, names, keyword lists). Every error
 * is one line FILE:LINE:COL. Introduced in step 02; docs/scene-format.md. */
#include "app/lexer.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/number.h"

/* Print `FILE:LINE:COL: message` and return false. */
bool lexer_fail(const Lexer *lx, int col, const char *fmt, ...)
{
  if (lx->quiet)
    return false;
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "%s:%d:%d: ", lx->file, lx->line, col);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  return false;
}

/* Length of the UTF-8 sequence at s (at most n bytes) when it is valid and
 * visible, 0 otherwise: invalid bytes, a byte-order mark, no-break and
 * zero-width spaces would be invisible or garbled in a message. */
static int visible_utf8(const unsigned char *s, int n)
{
  int len = s[0] >= 0xf0 ? 4 : s[0] >= 0xe0 ? 3 : s[0] >= 0xc2 ? 2 : 0;
  if (len == 0 || len > n || s[0] > 0xf4)
    return 0;
  unsigned cp = s[0] & (0x7f >> len);
  for (int k = 1; k < len; k++) {
    if ((s[k] & 0xc0) != 0x80)
      return 0;
    cp = cp << 6 | (s[k] & 0x3f);
  }
  bool overlong = (len == 3 && cp < 0x800) || (len == 4 && (cp < 0x10000 || cp > 0x10ffff));
  bool invisible = cp == 0xa0 || cp == 0xad || (cp >= 0x2000 && cp <= 0x200f) ||
                   (cp >= 0x2028 && cp <= 0x202f) || cp == 0x2060 || cp == 0xfeff ||
                   (cp >= 0xd800 && cp <= 0xdfff);
  return overlong || invisible ? 0 : len;
}

/* What the next token is, for messages: 'text' (its first 40 bytes, bytes
 * that would not show written \xNN) or "end of line". */
static const char *found(const Lexer *lx, char *buf, size_t size)
{
  if (lx->pos >= lx->n)
    return "end of line";
  const Token *t = &lx->tok[lx->pos];
  const unsigned char *s = (const unsigned char *)t->s;
  int n = t->len > 40 ? 40 : t->len;
  size_t k = 0;
  buf[k++] = '\'';
  for (int i = 0; i < n && k + 6 < size;) {
    int len = s[i] < 0x80 ? 1 : visible_utf8(s + i, n - i);
    if (len == 0)
      k += (size_t)snprintf(buf + k, size - k, "\\x%02x", s[i++]);
    for (; len > 0; len--)
      buf[k++] = (char)s[i++];
  }
  buf[k++] = '\'';
  buf[k] = '\0';
  return buf;
}

static int next_col(const Lexer *lx)
{
  return lx->pos < lx->n ? lx->tok[lx->pos].col : lx->end_col;
}

bool lexer_is(const Token *t, const char *word)
{
  int k = 0; /* stops at word's NUL too: a token holds no NUL */
  while (k < t->len && t->s[k] == word[k])
    k++;
  return k == t->len && word[k] == '\0';
}

void lexer_init(Lexer *lx, const char *file, const char *text, size_t len)
{
  memset(lx, 0, sizeof *lx);
  lx->file = file;
  lx->next = text;
  lx->end = text + len;
}

void lexer_skip_bom(Lexer *lx)
{
  if (lx->end - lx->next >= 3 && memcmp(lx->next, "\xef\xbb\xbf", 3) == 0)
    lx->next += 3;
}

/* A byte that belongs to a word: printable, not '#' (bytes >= 128 too, for
 * messages that quote them). */
static bool word_byte(unsigned char c)
{
  return c > ' ' && c != '#' && c != 127;
}

static bool space_byte(unsigned char c)
{
  return c == ' ' || c == '\t' || c == '\r';
}

/* The first byte at or after s, before stop, that is not a word byte. */
static const char *skip_word(const char *s, const char *stop)
{
  while (s < stop && word_byte((unsigned char)*s))
    s++;
  return s;
}

/* Skip a comment to the end of its line; a NUL byte in it is still refused. */
static const char *skip_comment(const Lexer *lx, const char *line, const char *s)
{
  for (; s < lx->end && *s != '\n'; s++)
    if (*s == '\0')
      return lexer_fail(lx, (int)(s - line) + 1, "expected text, found the control "
                        "byte 0x00"), NULL;
  return s;
}

/* Split the line starting at `line` into lx->tok; returns its end (the '\n'
 * or the end of the text), NULL after an error. */
static const char *split(Lexer *lx, const char *line)
{
  const char *s = line, *end = lx->end;
  for (;;) {
    while (s < end && space_byte((unsigned char)*s))
      s++;
    if (s == end || *s == '\n')
      return s;
    int col = (int)(s - line) + 1;
    if (*s == '#')
      return skip_comment(lx, line, s);
    if (!word_byte((unsigned char)*s))
      return lexer_fail(lx, col, "expected text, found the control byte 0x%02x",
                        (unsigned char)*s), NULL;
    if (lx->n == LEXER_MAX_TOKENS)
      return lexer_fail(lx, col, "expected at most %d words on a line, found more",
                        LEXER_MAX_TOKENS), NULL;
    const char *w = s, *stop = end - w > LEXER_TOKEN_MAX ? w + LEXER_TOKEN_MAX : end;
    s = skip_word(s, stop);
    if (s - w == LEXER_TOKEN_MAX)
      return lexer_fail(lx, col, "expected a word of at most %d characters, found a "
                        "longer one", LEXER_TOKEN_MAX - 1), NULL;
    lx->tok[lx->n++] = (Token){w, (int)(s - w), col};
    lx->end_col = (int)(s - line) + 1;
  }
}

int lexer_line(Lexer *lx)
{
  while (lx->next < lx->end) {
    const char *line = lx->next;
    lx->line++;
    lx->n = lx->pos = 0;
    const char *s = split(lx, line);
    if (!s)
      return -1;
    lx->next = s < lx->end ? s + 1 : s;
    if (lx->n > 0)
      return 1;
  }
  return 0;
}

bool lexer_peek_is(const Lexer *lx, const char *word)
{
  return lx->pos < lx->n && lexer_is(&lx->tok[lx->pos], word);
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
  char buf[192], list[256] = "", hint[96] = "";
  int best = LEXER_TOKEN_MAX;
  const Token *t = &lx->tok[lx->pos];
  bool full = false;
  for (int k = 0; k < n_words; k++) {
    size_t used = strlen(list);
    full = full || used + strlen(words[k]) + 7 >= sizeof list; /* ", word" and ", ..." */
    if (!full)
      snprintf(list + used, sizeof list - used, "%s%s", k ? ", " : "", words[k]);
    else if (!strstr(list, "..."))
      snprintf(list + used, sizeof list - used, ", ...");
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
 * says ">= 0"). Below the normal float range (a subnormal, or an underflow
 * to 0) is refused like an overflow: write 0. */
bool lexer_number(Lexer *lx, const char *what, bool nonneg, float *out)
{
  char buf[192];
  if (lx->pos >= lx->n)
    return lexer_fail(lx, lx->end_col, "expected %s, found end of line", what);
  const Token *t = &lx->tok[lx->pos];
  float v = 0.0f;
  switch (number_parse(t->s, t->len, &v)) {
  case NUMBER_BAD:
    return lexer_fail(lx, t->col, "expected %s, found %s", what, found(lx, buf, sizeof buf));
  case NUMBER_NONFINITE:
    return lexer_fail(lx, t->col, "expected %s, found a non-finite value %s", what,
                      found(lx, buf, sizeof buf));
  case NUMBER_TINY:
    return lexer_fail(lx, t->col, "expected %s, found %s, below the smallest normal "
                      "float 1.2e-38 (write 0)", what, found(lx, buf, sizeof buf));
  case NUMBER_OK:
    break;
  }
  if (nonneg && v < 0.0f)
    return lexer_fail(lx, t->col, "expected %s, found %s", what, found(lx, buf, sizeof buf));
  lx->pos++;
  *out = v;
  return true;
}

bool lexer_colour(Lexer *lx, const char *what, float max, vec3s *out)
{
  for (int k = 0; k < 3; k++) {
    int col = next_col(lx);
    if (!lexer_number(lx, what, true, &out->raw[k]))
      return false;
    if (out->raw[k] > max) {
      const Token *t = &lx->tok[lx->pos - 1];
      bool power = max == LEXER_MAX_POWER;
      return lexer_fail(lx, col, "expected %s, found '%.*s', above %s, the most %s may be "
                        "(a colour times a light must fit in a float)", what, t->len, t->s,
                        power ? "1e18" : "1e9",
                        power ? "a light's power" : "a colour or an irradiance");
    }
  }
  return true;
}

/* A whole number in [lo, hi]. */
bool lexer_int(Lexer *lx, const char *what, int lo, int hi, int *out)
{
  char buf[192];
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

bool lexer_name_valid(const char *s, int len, int max_len)
{
  bool ok = len >= 1 && len <= max_len && (s[0] == '_' || (s[0] | 32) >= 'a') &&
            (s[0] | 32) <= 'z';
  for (int k = 1; ok && k < len; k++)
    ok = s[k] == '_' || (s[k] >= '0' && s[k] <= '9') ||
         ((s[k] | 32) >= 'a' && (s[k] | 32) <= 'z');
  return ok;
}

bool lexer_name(Lexer *lx, const char *what, int max_len, Token *out)
{
  char buf[192];
  if (lx->pos >= lx->n)
    return lexer_fail(lx, lx->end_col, "expected %s, found end of line", what);
  const Token *t = &lx->tok[lx->pos];
  if (!lexer_name_valid(t->s, t->len, max_len))
    return lexer_fail(lx, t->col, "expected %s (letters, digits, '_', at most %d "
                      "characters), found %s", what, max_len, found(lx, buf, sizeof buf));
  *out = *t;
  lx->pos++;
  return true;
}

bool lexer_expect_end(Lexer *lx)
{
  char buf[192];
  if (lx->pos < lx->n)
    return lexer_fail(lx, lx->tok[lx->pos].col, "expected end of line, found an extra "
                      "value %s", found(lx, buf, sizeof buf));
  return true;
}
