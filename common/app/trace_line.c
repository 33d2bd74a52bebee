/* Trace lines (common/app/trace_line.h): building them, printing them as
 * indented text or as JSON (one line per trace line, so that the file is
 * valid JSON and each line parses alone), and reading the JSON back
 * (tools/loop/trace-diff.c). README.md, "For students"; docs/tracing.md. */
#include "app/trace_line.h"

#include <stdlib.h>
#include <string.h>

bool trace_lines_push(TraceLines *lines, const TraceLine *line)
{
  if (lines->n == lines->cap) {
    int cap = lines->cap ? 2 * lines->cap : 64;
    TraceLine *bigger = realloc(lines->line, (size_t)cap * sizeof *bigger);
    if (!bigger)
      return false;
    lines->line = bigger;
    lines->cap = cap;
  }
  lines->line[lines->n++] = *line;
  return true;
}

void trace_lines_free(TraceLines *lines)
{
  free(lines->line);
  *lines = (TraceLines){0};
}

TraceLine *trace_add(TraceLines *lines, int depth, const char *key, const char *doc)
{
  TraceLine line = {.depth = depth};
  snprintf(line.key, sizeof line.key, "%s", key);
  snprintf(line.doc, sizeof line.doc, "%s", doc);
  return trace_lines_push(lines, &line) ? &lines->line[lines->n - 1] : NULL;
}

static TraceField *field(TraceLine *line, const char *name)
{
  if (!line || line->n_fields == TRACE_FIELDS)
    return NULL;
  TraceField *f = &line->f[line->n_fields++];
  *f = (TraceField){0};
  snprintf(f->name, sizeof f->name, "%s", name);
  return f;
}

void trace_num(TraceLine *line, const char *name, double v)
{
  TraceField *f = field(line, name);
  if (f) {
    f->n = 1;
    f->v[0] = v;
  }
}

void trace_vec(TraceLine *line, const char *name, vec3s v)
{
  TraceField *f = field(line, name);
  if (f) {
    f->n = 3;
    for (int c = 0; c < 3; c++)
      f->v[c] = v.raw[c];
  }
}

void trace_vec2(TraceLine *line, const char *name, vec2s v)
{
  TraceField *f = field(line, name);
  if (f) {
    f->n = 2;
    f->v[0] = v.x;
    f->v[1] = v.y;
  }
}

void trace_word(TraceLine *line, const char *name, const char *word)
{
  TraceField *f = field(line, name);
  if (f)
    snprintf(f->word, sizeof f->word, "%s", word);
}

/* One field's value: "0.5", "(1, 2, 3)" or the word; `digits` significant. */
static int value_text(const TraceField *f, int digits, bool json, char *buf, size_t size)
{
  if (f->n == 0)
    return snprintf(buf, size, json ? "\"%s\"" : "%s", f->word);
  if (f->n == 1)
    return snprintf(buf, size, "%.*g", digits, f->v[0]);
  int len = snprintf(buf, size, json ? "[" : "(");
  for (int c = 0; c < f->n && len >= 0 && (size_t)len < size; c++)
    len += snprintf(buf + len, size - (size_t)len, "%s%.*g", c ? ", " : "", digits, f->v[c]);
  if (len >= 0 && (size_t)len < size)
    len += snprintf(buf + len, size - (size_t)len, json ? "]" : ")");
  return len;
}

void trace_line_text(const TraceLine *line, char *buf, size_t size)
{
  int indent = 2 * line->depth, width = indent < 20 ? 20 - indent : 0;
  int len = snprintf(buf, size, "%*s%-*s", indent, "", width, line->key);
  for (int k = 0; k < line->n_fields && len >= 0 && (size_t)len < size; k++) {
    /* An instance's name needs no "id = ". */
    bool id = !strcmp(line->f[k].name, "id");
    len += snprintf(buf + len, size - (size_t)len, "%s%s%s", k ? "  " : " ",
                    id ? "" : line->f[k].name, id ? "" : " = ");
    if (len >= 0 && (size_t)len < size)
      len += value_text(&line->f[k], 6, false, buf + len, size - (size_t)len);
  }
}

static void print_json(const TraceLine *line, bool last, FILE *out)
{
  fprintf(out, "{\"depth\": %d, \"key\": \"%s\", \"doc\": \"", line->depth, line->key);
  for (const char *c = line->doc; *c; c++)
    fprintf(out, *c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
  fputc('"', out);
  for (int k = 0; k < line->n_fields; k++) {
    char value[256];
    value_text(&line->f[k], 9, true, value, sizeof value);
    fprintf(out, ", \"%s\": %s", line->f[k].name, value);
  }
  fprintf(out, "}%s\n", last ? "" : ",");
}

void trace_lines_print(const TraceLines *lines, bool json, FILE *out)
{
  for (int k = 0; k < lines->n; k++) {
    if (json) {
      print_json(&lines->line[k], k == lines->n - 1, out);
      continue;
    }
    char text[1024];
    trace_line_text(&lines->line[k], text, sizeof text);
    fprintf(out, "%s\n", text);
  }
}

/* ---------------------------------------------------------------- parsing */

static const char *skip(const char *s)
{
  while (*s == ' ' || *s == '\t')
    s++;
  return s;
}

/* A JSON string without escapes other than \" and \\ into buf; NULL if none. */
static const char *string(const char *s, char *buf, size_t size)
{
  s = skip(s);
  if (*s++ != '"')
    return NULL;
  size_t n = 0;
  for (; *s && *s != '"'; s++) {
    if (*s == '\\' && s[1])
      s++;
    if (n + 1 < size)
      buf[n++] = *s;
  }
  buf[n] = 0;
  return *s == '"' ? s + 1 : NULL;
}

/* A number, an array of up to 3 numbers or a string, into f. */
static const char *value(const char *s, TraceField *f)
{
  s = skip(s);
  if (*s == '"')
    return string(s, f->word, sizeof f->word);
  bool array = *s == '[';
  s += array;
  for (f->n = 0; f->n < 3;) {
    char *end;
    f->v[f->n] = strtod(s, &end);
    if (end == s)
      return NULL;
    f->n++;
    s = skip(end);
    if (!array || *s != ',')
      break;
    s++;
  }
  if (array && *s++ != ']')
    return NULL;
  return s;
}

bool trace_line_parse(const char *s, TraceLine *line)
{
  *line = (TraceLine){0};
  s = skip(s);
  if (*s++ != '{')
    return false;
  for (;;) {
    char name[TRACE_NAME];
    if (!(s = string(s, name, sizeof name)) || *(s = skip(s)) != ':')
      return false;
    s++;
    TraceField f = {0};
    if (!strcmp(name, "key") || !strcmp(name, "doc")) {
      bool key = name[0] == 'k';
      if (!(s = string(s, key ? line->key : line->doc, key ? sizeof line->key : sizeof line->doc)))
        return false;
    } else if (!strcmp(name, "depth")) {
      if (!(s = value(s, &f)) || f.n != 1)
        return false;
      line->depth = (int)f.v[0];
    } else {
      if (line->n_fields == TRACE_FIELDS || !(s = value(s, &f)))
        return false;
      snprintf(f.name, sizeof f.name, "%s", name);
      line->f[line->n_fields++] = f;
    }
    s = skip(s);
    if (*s == '}')
      return true;
    if (*s++ != ',')
      return false;
  }
}
