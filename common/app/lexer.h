/* Scene-file lexer: the words of one line with their columns, and readers for
 * the values statements take. Every failure prints one line
 * `FILE:LINE:COL: expected ..., found ...` and returns false.
 * Introduced in step 02; docs/scene-format.md. */
#ifndef RT_LEXER_H
#define RT_LEXER_H

#include <stdbool.h>
#include <stddef.h>
#include "vec.h"

enum { LEXER_MAX_TOKENS = 64, LEXER_TOKEN_MAX = 64 };

/* Coordinates are at most this in magnitude; lengths lie in
 * [1 / LEXER_MAX_COORD, LEXER_MAX_COORD]: squares and differences then fit in
 * a float (docs/scene-format.md, "Limits"). */
#define LEXER_MAX_COORD 1e18f
#define LEXER_MIN_LENGTH 1e-18f
/* A colour (a material's, the ambient light, a directional light's
 * irradiance) is at most LEXER_MAX_COLOR, a point or area light's power at
 * most LEXER_MAX_POWER: a colour times a colour, or times a light's power
 * over any distance the scene's scale allows, fits in a float
 * (docs/scene-format.md, "Limits"). */
#define LEXER_MAX_COLOR 1e9f
#define LEXER_MAX_POWER 1e18f

typedef struct Token {
  const char *s; /* into the text, not terminated */
  int len, col;  /* col counts bytes from 1 */
} Token;

typedef struct Lexer {
  const char *file;          /* name used in messages */
  const char *next, *end;    /* the text not read yet */
  int line;                  /* current line, from 1 */
  Token tok[LEXER_MAX_TOKENS];
  int n, pos;                /* words on this line, next one to read */
  int end_col;               /* column just past the line's last word */
  bool quiet;                /* errors are not printed (lexer_fail only fails) */
} Lexer;

/* Start reading the `len` bytes of `text`; `file` names it in messages. */
void lexer_init(Lexer *lx, const char *file, const char *text, size_t len);

/* Skip a UTF-8 byte-order mark at the start of the text, if any (a file's
 * start only: anywhere else it is part of a word). */
void lexer_skip_bom(Lexer *lx);

/* Split the next line that has words (comments start at '#'). Returns 1 with
 * the words in lx->tok, 0 at the end of the text, -1 after printing an error
 * (control characters, words too long, too many words). */
int lexer_line(Lexer *lx);

/* True when token `t` is `word`. */
bool lexer_is(const Token *t, const char *word);

/* True when the next word is `word` (not consumed). */
bool lexer_peek_is(const Lexer *lx, const char *word);

/* Print `FILE:LINE:COL: message` for the current line (unless quiet);
 * returns false. */
bool lexer_fail(const Lexer *lx, int col, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Fail on the next word, an unknown one: list `words`, suggest the nearest. */
bool lexer_fail_unknown(const Lexer *lx, const char *what,
                        const char *const *words, int n_words);

/* Readers of the next word(s). `what` names the value in messages. */
bool lexer_number(Lexer *lx, const char *what, bool nonneg, float *out);

/* Three numbers >= 0, each at most `max`: LEXER_MAX_COLOR (a colour),
 * LEXER_MAX_POWER (a light's power) or INFINITY (any finite value); false
 * (printed) at the first that is not. */
bool lexer_colour(Lexer *lx, const char *what, float max, vec3s *out);
bool lexer_int(Lexer *lx, const char *what, int lo, int hi, int *out);
/* A name (letter or '_', then letters, digits, '_'), as a token of the text. */
bool lexer_name(Lexer *lx, const char *what, int max_len, Token *out);
/* Whether the `len` bytes at s make a name of at most max_len bytes. */
bool lexer_name_valid(const char *s, int len, int max_len);
bool lexer_expect_end(Lexer *lx);

#endif
