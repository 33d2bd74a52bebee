/* A small JSON reader for the project's own files (tests/run.sh's results
 * files): the whole text parsed into a tree of nodes; look members up by
 * name. Strings keep their escapes decoded (\n, \", \\, \t; \u as '?').
 * Used by tools/loop/report.c. */
#ifndef RT_JSON_H
#define RT_JSON_H

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

typedef enum JsonKind { JSON_NULL, JSON_BOOL, JSON_NUMBER, JSON_STRING, JSON_ARRAY, JSON_OBJECT } JsonKind;

typedef struct Json {
  JsonKind kind;
  char *name;          /* member name inside an object, else NULL */
  char *text;          /* JSON_STRING */
  double number;       /* JSON_NUMBER, JSON_BOOL (0 or 1) */
  struct Json *child;  /* first element or member */
  struct Json *next;   /* next sibling */
} Json;

static const char *json_value(const char *s, Json *out);

static const char *json_skip(const char *s)
{
  while (*s == ' ' || *s == '\n' || *s == '\r' || *s == '\t')
    s++;
  return s;
}

static const char *json_string(const char *s, char **out)
{
  if (*s++ != '"')
    return NULL;
  char *buf = malloc(strlen(s) + 1), *w = buf;
  for (; *s && *s != '"'; s++) {
    if (*s != '\\') {
      *w++ = *s;
      continue;
    }
    s++;
    *w++ = *s == 'n' ? '\n' : *s == 't' ? '\t' : *s == 'u' ? '?' : *s;
    if (*s == 'u')
      s += 4;
  }
  *w = 0;
  *out = buf;
  return *s == '"' ? s + 1 : NULL;
}

/* Elements (or members when `object`) up to `close`. */
static const char *json_list(const char *s, Json *out, bool object, char close)
{
  Json **tail = &out->child;
  s = json_skip(s + 1);
  if (*s == close)
    return s + 1;
  for (;;) {
    Json *item = calloc(1, sizeof *item);
    *tail = item;
    tail = &item->next;
    s = json_skip(s);
    if (object && (!(s = json_string(s, &item->name)) || *(s = json_skip(s)) != ':'))
      return NULL;
    if (!(s = json_value(json_skip(s + object), item)))
      return NULL;
    s = json_skip(s);
    if (*s == close)
      return s + 1;
    if (*s++ != ',')
      return NULL;
  }
}

static const char *json_value(const char *s, Json *out)
{
  s = json_skip(s);
  if (*s == '{' || *s == '[') {
    out->kind = *s == '{' ? JSON_OBJECT : JSON_ARRAY;
    return json_list(s, out, *s == '{', *s == '{' ? '}' : ']');
  }
  if (*s == '"') {
    out->kind = JSON_STRING;
    return json_string(s, &out->text);
  }
  if (!strncmp(s, "true", 4) || !strncmp(s, "false", 5)) {
    out->kind = JSON_BOOL;
    out->number = *s == 't';
    return s + (*s == 't' ? 4 : 5);
  }
  if (!strncmp(s, "null", 4))
    return s + 4;
  char *end;
  out->kind = JSON_NUMBER;
  out->number = strtod(s, &end);
  return end == s ? NULL : end;
}

/* The member `name` of an object, NULL when absent. */
static const Json *json_get(const Json *obj, const char *name)
{
  for (const Json *m = obj ? obj->child : NULL; m; m = m->next)
    if (m->name && !strcmp(m->name, name))
      return m;
  return NULL;
}

static const char *json_text(const Json *obj, const char *name)
{
  const Json *m = json_get(obj, name);
  return m && m->kind == JSON_STRING ? m->text : "";
}

static bool json_true(const Json *obj, const char *name)
{
  const Json *m = json_get(obj, name);
  return m && m->kind == JSON_BOOL && m->number != 0.0;
}

static void json_free(Json *j)
{
  while (j) {
    Json *next = j->next;
    json_free(j->child);
    free(j->name);
    free(j->text);
    free(j);
    j = next;
  }
}

#endif
