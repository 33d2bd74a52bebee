/* trace-diff: a step's trace of one pixel against its reference trace
 * (tests/traces/NN-name/X_Y.json, written by `make regen` from the
 * solution). Runs the step's binary with the reference's options, reads both
 * JSON traces line by line and prints the first line whose values differ
 * beyond the tolerance, both values and the doc section to read. `make
 * trace-step N` runs it; docs/tracing.md.
 *
 * usage: trace-diff [--tol REL ABS] BIN REF.json [WHAT]
 * Exit status: 0 the traces agree, 1 they differ, 2 bad usage or files. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/trace_line.h"

enum { ARGS_MAX = 64, TEXT = 1024 };

typedef struct TraceFile {
  char step[64], args[512];
  int x, y;
  TraceLines lines;
} TraceFile;

/* `"name": 12` or `"name": "text"` in the header line. */
static const char *header_field(const char *line, const char *name)
{
  char pattern[64];
  snprintf(pattern, sizeof pattern, "\"%s\": ", name);
  const char *at = strstr(line, pattern);
  return at ? at + strlen(pattern) : NULL;
}

static void header_string(const char *line, const char *name, char *out, size_t size)
{
  const char *v = header_field(line, name);
  size_t n = 0;
  if (v && *v++ == '"')
    for (; *v && *v != '"' && n + 1 < size; v++)
      out[n++] = *v == '\\' && v[1] ? *++v : *v;
  out[n] = 0;
}

/* Read a JSON trace from `f`; false (one line printed, naming `what`) when it
 * is not one. */
static bool read_trace(FILE *f, const char *what, TraceFile *tr)
{
  char line[4096];
  *tr = (TraceFile){0};
  if (!fgets(line, sizeof line, f) || !header_field(line, "lines")) {
    fprintf(stderr, "trace-diff: %s: expected a JSON trace (--trace-format json), found "
            "'%.60s'\n", what, line);
    return false;
  }
  header_string(line, "step", tr->step, sizeof tr->step);
  header_string(line, "args", tr->args, sizeof tr->args);
  tr->x = atoi(header_field(line, "x") ? header_field(line, "x") : "-1");
  tr->y = atoi(header_field(line, "y") ? header_field(line, "y") : "-1");
  for (int n = 2; fgets(line, sizeof line, f); n++) {
    if (line[0] == ']')
      return true;
    TraceLine l;
    if (!trace_line_parse(line, &l) || !trace_lines_push(&tr->lines, &l)) {
      fprintf(stderr, "trace-diff: %s:%d: expected a trace line, found '%.60s'\n", what, n,
              line);
      return false;
    }
  }
  fprintf(stderr, "trace-diff: %s: the trace ends early (no closing ']}')\n", what);
  return false;
}

/* Run BIN ARGS --trace X Y --trace-format json and read its trace; its
 * stderr goes to `err`. */
static bool run_trace(const char *bin, const TraceFile *ref, FILE *err, TraceFile *got)
{
  char args[512], x[16], y[16], *argv[ARGS_MAX + 8];
  int argc = 0;
  snprintf(args, sizeof args, "%s", ref->args);
  snprintf(x, sizeof x, "%d", ref->x);
  snprintf(y, sizeof y, "%d", ref->y);
  argv[argc++] = (char *)bin;
  for (char *w = strtok(args, " "); w && argc < ARGS_MAX; w = strtok(NULL, " "))
    argv[argc++] = w;
  char *tail[] = {"--trace", x, y, "--trace-format", "json", NULL};
  memcpy(argv + argc, tail, sizeof tail);
  int out[2];
  if (pipe(out) != 0)
    return false;
  pid_t pid = fork();
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    dup2(fileno(err), STDERR_FILENO);
    close(out[0]);
    execv(bin, argv);
    fprintf(stderr, "trace-diff: cannot run %s: %s\n", bin, strerror(errno));
    _exit(127);
  }
  close(out[1]);
  FILE *f = fdopen(out[0], "r");
  bool ok = f && read_trace(f, bin, got);
  if (f)
    fclose(f);
  int status = 0;
  waitpid(pid, &status, 0);
  return ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

typedef struct Tolerance {
  double rel, abs;
} Tolerance;

/* The first field of b that differs from a's, -1 when none; -2 when the
 * lines are not the same quantity (key, depth or field names). */
static int differs(const TraceLine *a, const TraceLine *b, Tolerance tol)
{
  if (a->depth != b->depth || strcmp(a->key, b->key) || a->n_fields != b->n_fields)
    return -2;
  for (int k = 0; k < a->n_fields; k++) {
    const TraceField *fa = &a->f[k], *fb = &b->f[k];
    if (strcmp(fa->name, fb->name))
      return -2;
    if (fa->n != fb->n || (fa->n == 0 && strcmp(fa->word, fb->word)))
      return k;
    /* The exported bytes may move by one code where the floats are within
     * tolerance of a rounding boundary. */
    double slack = !strcmp(a->key, "byte") ? 1.0 : 0.0;
    for (int c = 0; c < fa->n; c++) {
      double x = fa->v[c], y = fb->v[c];
      double allowed = fmax(slack, tol.abs + tol.rel * fmax(fabs(x), fabs(y)));
      if (!(x == y || fabs(x - y) <= allowed))
        return k;
    }
  }
  return -1;
}

static void show(const char *label, const TraceLine *line, int field)
{
  char text[TEXT];
  TraceLine only = *line;
  if (field >= 0) { /* that field alone, after the instance it is about */
    only.n_fields = 0;
    for (int k = 0; k < line->n_fields; k++)
      if (k == field || (k < field && !strcmp(line->f[k].name, "id")))
        only.f[only.n_fields++] = line->f[k];
    only.depth = 0;
  }
  trace_line_text(&only, text, sizeof text);
  printf("  %-9s %s\n", label, text);
}

/* The first line of `got` that differs from `ref`'s (and in *field, which of
 * its fields, -2 for a different quantity); -1 when none does. */
static int first_difference(const TraceFile *ref, const TraceFile *got, Tolerance tol,
                            int *field)
{
  int n = ref->lines.n < got->lines.n ? ref->lines.n : got->lines.n;
  for (int k = 0; k < n; k++)
    if ((*field = differs(&ref->lines.line[k], &got->lines.line[k], tol)) != -1)
      return k;
  *field = -2;
  return ref->lines.n == got->lines.n ? -1 : n;
}

/* Line k and its parents (the enclosing lines), then both values. */
static void explain(const TraceFile *ref, const TraceFile *got, int k, int field,
                    Tolerance tol)
{
  printf("  line %d of %d differs; the lines above it agree. Where it is:\n", k + 1,
         ref->lines.n);
  const TraceLine *at = k < ref->lines.n ? &ref->lines.line[k] : &got->lines.line[k];
  int parents[32], n = 0;
  for (int d = at->depth - 1, j = k - 1; d >= 0 && j >= 0 && n < 32; j--)
    if (ref->lines.line[j].depth == d) {
      parents[n++] = j;
      d--;
    }
  while (n-- > 0) {
    char text[TEXT];
    trace_line_text(&ref->lines.line[parents[n]], text, sizeof text);
    printf("            %s\n", text);
  }
  if (k >= ref->lines.n || k >= got->lines.n) {
    printf(k >= got->lines.n ? "  expected  one more line:\n" : "  got       one line more:\n");
    show("", at, -1);
  } else {
    show("expected", &ref->lines.line[k], field < 0 ? -1 : field);
    show("got", &got->lines.line[k], field < 0 ? -1 : field);
    if (field >= 0)
      printf("  (numbers agree when within %g relative or %g absolute)\n", tol.rel, tol.abs);
  }
  printf("  read %s\n", at->doc);
}

int main(int argc, char **argv)
{
  Tolerance tol = {1e-4, 1e-6};
  int a = 1;
  if (argc > 3 && !strcmp(argv[1], "--tol")) {
    tol = (Tolerance){atof(argv[2]), atof(argv[3])};
    a = 4;
  }
  if (argc - a < 2) {
    fprintf(stderr, "usage: trace-diff [--tol REL ABS] BIN REF.json [WHAT]\n");
    return 2;
  }
  const char *bin = argv[a], *ref_path = argv[a + 1], *what = argc - a > 2 ? argv[a + 2] : "";
  FILE *f = fopen(ref_path, "r");
  TraceFile ref, got;
  if (!f) {
    fprintf(stderr, "trace-diff: cannot read %s: %s\n", ref_path, strerror(errno));
    return 2;
  }
  bool ok = read_trace(f, ref_path, &ref);
  fclose(f);
  if (!ok)
    return 2;
  char cmd[1024];
  snprintf(cmd, sizeof cmd, "%s%s%s --trace %d %d", bin, *ref.args ? " " : "", ref.args,
           ref.x, ref.y);
  FILE *err = tmpfile();
  if (!err || !run_trace(bin, &ref, err, &got)) {
    printf("FAIL  %s: %s\n  it printed no trace:\n", cmd, what);
    if (err) {
      rewind(err);
      for (int c; (c = fgetc(err)) != EOF;)
        putchar(c);
    }
    return 1;
  }
  fclose(err);
  int field, k = first_difference(&ref, &got, tol, &field);
  if (k < 0) {
    printf("PASS  %s: %s (%d lines agree)\n", cmd, what, ref.lines.n);
  } else {
    printf("FAIL  %s: %s\n", cmd, what);
    explain(&ref, &got, k, field, tol);
  }
  trace_lines_free(&ref.lines);
  trace_lines_free(&got.lines);
  return k < 0 ? 0 : 1;
}
