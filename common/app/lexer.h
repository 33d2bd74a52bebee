/* Scene-file lexer: the words of one line with their columns, and readers for
 * the values statements take. Every failure prints one line
 * `FILE:LINE:COL: expected ..., found ...` and returns false.
 * Introduced in step 02; docs/scene-format.md. */
#ifndef RT_LEXER_H
#define RT_LEXER_H

#include <stdbool.h>
#include "material.h"

enum { LEXER_MAX_TOKENS = 64, LEXER_TOKEN_MAX = 64 };

typedef struct Token {
  const char *s;
  int len, col; /* col counts bytes from 1 */
} Token;

typedef struct Lexer {
  const char *file;          /* name used in messages */
  const char *next;          /* start of the next line in the text */
  int line;                  /* current line, from 1 */
  Token tok[LEXER_MAX_TOKENS];
  int n, pos;                /* words on this line, next one to read */
  int end_col;               /* column just past the line's last word */
} Lexer;

/* Start reading `text` (NUL-terminated); `file` names it in messages. */
void lexer_init(Lexer *lx, const char *file, const char *text);

/* Split the next line that has words (comments start at '#'). Returns 1 with
 * the words in lx->tok, 0 at the end of the text, -1 after printing an error
 * (control characters, words too long, too many words). */
int lexer_line(Lexer *lx);

/* True when the next word is `word` (not consumed). */
bool lexer_peek_is(const Lexer *lx, const char *word);

/* Print `FILE:LINE:COL: message` for the current line; returns false. */
bool lexer_fail(const Lexer *lx, int col, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Fail on the next word, an unknown one: list `words`, suggest the nearest. */
bool lexer_fail_unknown(const Lexer *lx, const char *what,
                        const char *const *words, int n_words);

/* Readers of the next word(s). `what` names the value in messages. */
bool lexer_number(Lexer *lx, const char *what, bool nonneg, float *out);
bool lexer_vec(Lexer *lx, const char *what, bool nonneg, vec3s *out);
bool lexer_int(Lexer *lx, const char *what, int lo, int hi, int *out);
bool lexer_name(Lexer *lx, const char *what, char out[MATERIAL_NAME_MAX]);
bool lexer_expect_end(Lexer *lx);

/* Keyword lists: `keyword values` pairs to the end of the line, any order. */
typedef enum KeyKind {
  KEY_VEC,    /* three numbers */
  KEY_COLOR,  /* three numbers >= 0 */
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
  int col;                 /* column of the keyword */
  int val_col;             /* column of its first value */
  char text[LEXER_TOKEN_MAX]; /* its first value as written */
  vec3s v;                 /* the vector, or v.x for KEY_NUM */
  char name[MATERIAL_NAME_MAX];
} Field;

enum { LEXER_MAX_KEYS = 6 };

/* Read the rest of the line as keyword lists of `keys` into `fields` (same
 * order); each keyword at most once, required ones present. `what` names the
 * statement in messages. */
bool lexer_fields(Lexer *lx, const char *what, const Key *keys, int n_keys,
                  Field *fields);

#endif
