/* The line a large scene is made of, read straight from the text
 * (reader/sphere_line.h). */
#include "reader/sphere_line.h"

#include <stdint.h>
#include <string.h>

#include "app/limits.h"
#include "app/lexer.h"
#include "reader/decimal.h"

bool sphere_line_on = true;

/* A material name a sphere line found: its bytes as two words, zero past its
 * length (at most 16 bytes). */
typedef struct RecentName {
  uint64_t w[2];
  int len, material;
} RecentName;

enum { RECENT_NAMES = 8 };

/* The last names found in one run of sphere lines, the oldest replaced. */
typedef struct Recent {
  RecentName name[RECENT_NAMES];
  unsigned n;
} Recent;

/* The word at s is `word` followed by one space. */
static bool word_then_space(const char *s, const char *end, const char *word, size_t len)
{
  return (size_t)(end - s) > len && memcmp(s, word, len) == 0 && s[len] == ' ';
}

/* The plain decimal at s, of fewer than LEXER_TOKEN_MAX bytes, then one
 * space: the byte after that space, NULL otherwise. Inlined into each of
 * sphere_line's four reads, decimal_prefix's short path with it (gcc left
 * it a call). */
__attribute__((always_inline)) static inline const char *number_then_space(const char *s,
                                                                          const char *end,
                                                                          float *v)
{
  const char *stop = decimal_prefix(s, end, v);
  return stop && stop < end && *stop == ' ' && stop - s < LEXER_TOKEN_MAX ? stop + 1 : NULL;
}

/* The word at s, up to the first '\n' or ' ' within 16 bytes: its length,
 * with its bytes in w[0], w[1], zero past it; -1 (w unset) when there is no
 * such byte there or fewer than 16 bytes are left. The first byte flagged by
 * (x - 0x01..) & ~x & 0x80.. is x's first zero byte (a borrow runs only
 * past a zero byte). */
static int name_words(const char *s, const char *end, uint64_t w[2])
{
  if (end - s < 16)
    return -1;
  memcpy(w, s, 2 * sizeof *w);
  const uint64_t ones = 0x0101010101010101u, highs = 0x8080808080808080u;
  for (int k = 0; k < 2; k++) {
    uint64_t nl = w[k] ^ 0x0A0A0A0A0A0A0A0Au, sp = w[k] ^ 0x2020202020202020u;
    uint64_t stop = (((nl - ones) & ~nl) | ((sp - ones) & ~sp)) & highs;
    if (stop) {
      int n = __builtin_ctzll(stop) >> 3;
      w[k] &= n ? ~0ull >> (64 - 8 * n) : 0;
      if (k == 0)
        w[1] = 0;
      return 8 * k + n;
    }
  }
  return -1;
}

/* The material of a name sphere_line found before (w, len as name_words
 * gives them); -1 when it is not one of the last RECENT_NAMES found in this
 * run of lines. Such a
 * name passed lexer_name_valid then, and names_find gives the same index
 * now: a material's index never changes while a text is parsed. */
static int recent_find(const Recent *recent, const uint64_t w[2], int len)
{
  unsigned n = recent->n < RECENT_NAMES ? recent->n : RECENT_NAMES;
  for (unsigned k = 0; k < n; k++) {
    const RecentName *r = &recent->name[k];
    if (r->len == len && r->w[0] == w[0] && r->w[1] == w[1])
      return r->material;
  }
  return -1;
}

/* The line a large scene is made of, `sphere center X Y Z radius R material
 * NAME`, read straight from the text: one space between words, plain
 * decimals, the name last and then the end of the line. 1 when it was such a
 * line (added, or -1 when out of memory), 0 for any other line, for a value
 * the statement refuses, and for any doubt: the general path (lexer_line,
 * statement) then reads it and says what is wrong. What this accepts the
 * general path accepts, with the same floats (decimal_prefix stops where
 * the lexer's word ends, at the space, and reads it as number_parse does) and
 * the same checks (fields_coordinate_ok, limits_length_ok,
 * lexer_name_valid, which a name among the last RECENT_NAMES found has
 * passed already: recent_find); tests/test_parse_pieces.c compares the two
 * on altered sphere lines and on texts of many lines and names. */
static int sphere_line(Parser *p, Recent *recent)
{
  Lexer *lx = &p->lx;
  const char *line = lx->next, *end = lx->end, *s = line;
  float v[4];
  if (!word_then_space(s, end, "sphere", 6) || !word_then_space(s + 7, end, "center", 6))
    return 0;
  s += 14;
  for (int k = 0; k < 3; k++)
    if (!(s = number_then_space(s, end, &v[k])) || !fields_coordinate_ok(v[k]))
      return 0;
  if (!word_then_space(s, end, "radius", 6) || !(s = number_then_space(s + 7, end, &v[3])) ||
      !limits_length_ok(v[3]) || !word_then_space(s, end, "material", 8))
    return 0;
  s += 9;
  const char *name = s;
  uint64_t w[2];
  int len = name_words(name, end, w);
  int material = len > 0 && name[len] == '\n' ? recent_find(recent, w, len) : -1;
  if (material >= 0) {
    s += len;
  } else {
    while (s < end && *s != '\n' && *s != ' ' && s - name < LEXER_TOKEN_MAX)
      s++;
    if ((s < end && *s != '\n') ||
        !lexer_name_valid(name, (int)(s - name), MATERIAL_NAME_MAX - 1))
      return 0;
    material = names_find(&p->names, parser_materials(p->scene), name, (int)(s - name));
    if (material >= 0 && len > 0)
      recent->name[recent->n++ % RECENT_NAMES] = (RecentName){{w[0], w[1]}, len, material};
  }
  lx->line++;
  lx->n = lx->pos = 0;
  lx->next = s < end ? s + 1 : s;
  Instance inst = {.shape = SHAPE_SPHERE,
                   .sphere = {.center = {{v[0], v[1], v[2]}}, .radius = v[3]},
                   .material = material};
  Token tok = {name, (int)(s - name), (int)(name - line) + 1};
  return parser_place_shape(p, &inst, &tok) ? 1 : -1;
}

int sphere_line_run(Parser *p)
{
  Recent recent = {.n = 0};
  int more = 1;
  while (sphere_line_on && (more = sphere_line(p, &recent)) > 0)
    ;
  return more < 0 ? -1 : 0;
}
