/* The parser's state and statements (common/app/parser_state.c), for whole
 * texts (common/app/parser.c). Internal to the parser;
 * docs/scene-format.md. */
#ifndef RT_PARSER_STATE_H
#define RT_PARSER_STATE_H


#include "app/lexer.h"
#include "app/names.h"
#include "scene.h"
#include "shapes.h"

/* Statements that may appear once per file. */
enum { ONCE_FILM, ONCE_CAMERA, ONCE_AMBIENT, ONCE_BACKGROUND, ONCE_SAMPLES,
       ONCE_LIGHT_SAMPLES, ONCE_COUNT };

/* A shape whose material was not defined yet where it was named: the name
 * is the parser's forward[name] (each such name is kept once, however many
 * shapes use it). */
typedef struct Pending {
  int instance, line, col, name;
} Pending;

typedef struct ForwardName {
  char name[MATERIAL_NAME_MAX];
} ForwardName;

typedef struct Parser {
  Lexer lx;
  Scene *scene;
  Names names;       /* material name -> index into scene->materials */
  Pending *pending;  /* in file order */
  int n_pending;
  ForwardName *forward; /* the names pending references use */
  int n_forward;
  Names forward_names;  /* name -> index into forward */
  int once_line[ONCE_COUNT]; /* where each once-statement was, 0: not yet */
  int room; /* 0: shapes go to the scene's growing array; > 0: a part of a
             * text (parser_part_parse), whose shapes go in place to
             * scene->instances[0 .. room), an array it does not own; -1: a
             * part given no room, which fails at its first shape */
} Parser;

/* The scene's materials as records of the names table. */
NameRecords parser_materials(const Scene *scene);

/* Start parsing `len` bytes of `text` into `scene` (scene_init'ed). */
void parser_begin(Parser *p, const char *file, const char *text, size_t len, Scene *scene);

/* Every statement to the end of the text; false after the first error
 * (printed unless p->lx.quiet). Materials named before their definition
 * are left in p->pending. */
bool parser_statements(Parser *p);

/* Append a reference to material `name` (`len` bytes) of instance
 * `instance`, at `line`, `col`, to resolve at the end; false when out of
 * memory. */
bool parser_pending_add(Parser *p, int instance, int line, int col, const char *name, int len);

/* Add a lit instance whose material, the name token `name`, is
 * inst->material (-1: not defined yet, resolved at the end); false when out
 * of memory, or (silently) when a part finds more shapes than its room. */
bool parser_place_shape(Parser *p, Instance *inst, const Token *name);

/* The statement table (parser_state.c's STATEMENTS), in the order messages
 * list it: k in [0, parser_statement_count()). Each statement's first word,
 * a valid line of it (a shape's names material `m`), and whether a file may
 * hold it once only. */
int parser_statement_count(void);
const char *parser_statement_word(int k);
const char *parser_statement_example(int k);
bool parser_statement_once(int k);

/* Resolve p->pending; false (printed) at the first undefined name. */
bool parser_resolve(Parser *p);

/* Free the parser's own memory (not the scene). */
void parser_end(Parser *p);

#endif
