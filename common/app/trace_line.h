/* The lines of a trace (`--trace X Y`, every step from 02): a key, a few
 * named values and the doc that explains them; built by the recorder
 * (app/trace_record.h), printed as indented text or as JSON lines (a trace
 * file), read back by tools/loop/trace-diff.c. docs/tracing.md. */
#ifndef RT_TRACE_LINE_H
#define RT_TRACE_LINE_H

#include <stdbool.h>
#include <stdio.h>

#include "vec.h"

/* One line of a trace: a key ("camera ray"), up to TRACE_FIELDS named values
 * (1 to 3 numbers, or a word), its indentation and the doc that explains it. */
enum { TRACE_FIELDS = 6, TRACE_NAME = 16, TRACE_WORD = 96 };

typedef struct TraceField {
  char name[TRACE_NAME];
  int n;               /* numbers in v (1 to 3); 0: the value is `word` */
  double v[3];
  char word[TRACE_WORD];
} TraceField;

typedef struct TraceLine {
  int depth;           /* indentation level, 0 = the pixel */
  char key[24];
  char doc[120];       /* "docs/04-phong.md, \"The math\"" */
  int n_fields;
  TraceField f[TRACE_FIELDS];
} TraceLine;

typedef struct TraceLines {
  TraceLine *line;     /* owned */
  int n, cap;
} TraceLines;

/* Append a copy of `line`; false when out of memory. */
bool trace_lines_push(TraceLines *lines, const TraceLine *line);
void trace_lines_free(TraceLines *lines);

/* Building lines: trace_add appends an empty line (NULL when out of memory;
 * the setters then do nothing), the setters append a field to it (nothing
 * past TRACE_FIELDS). */
TraceLine *trace_add(TraceLines *lines, int depth, const char *key, const char *doc);
void trace_num(TraceLine *line, const char *name, double v);
void trace_vec(TraceLine *line, const char *name, vec3s v);
void trace_vec2(TraceLine *line, const char *name, vec2s v);
void trace_word(TraceLine *line, const char *name, const char *word);

/* The text of one line as --trace prints it, indented, without a newline. */
void trace_line_text(const TraceLine *line, char *buf, size_t size);

/* Print lines as indented text, or as the JSON lines of a trace file. */
void trace_lines_print(const TraceLines *lines, bool json, FILE *out);

/* Parse one JSON line written by trace_lines_print; false when it is not one. */
bool trace_line_parse(const char *text, TraceLine *line);

#endif
