/* trace-diff: a step's trace of one pixel against its reference trace
 * (tests/traces/NN-name/X_Y.json, written by `make regen` from the
 * solution). Runs the step's binary with the reference's options, reads both
 * JSON traces and prints the first line whose values differ beyond the
 * tolerance, both values and the doc section to read. `make trace-step N`
 * runs it; docs/tracing.md.
 *
 * It compares what the lesson fixes, not the solution's conventions. Lines
 * are compared in order, except:
 * - a pixel's camera samples (a `sample K` line and the lines under it) are
 *   compared as a set: each expected sample must be among the samples taken,
 *   in any order and under any number K (an adaptive subdivision may visit
 *   the quarters in another order);
 * - an area light's samples (`light K area`: shadow rays, blocked, diffuse,
 *   specular) are compared as means over the pixel's camera samples, within
 *   4 standard errors of the differences between the same camera samples of
 *   both traces: another valid sampling of the light (which edge gets which
 *   coordinate, another pattern) moves each camera sample's value, not their
 *   mean. The pixel's totals after them
 *   (terms, colour, bytes) get the same allowance. The sample count is
 *   compared exactly.
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
  double extra[3]; /* per channel: the allowance of the sampled means above */
} Tolerance;

/* A camera sample's line: "sample K", K not compared. */
static bool is_sample(const TraceLine *l)
{
  return l->depth == 0 && !strncmp(l->key, "sample ", 7);
}

/* A field that another valid sampling of an area light moves: compared as a
 * mean over the camera samples, not line by line. */
static bool sampled_field(const TraceLine *l, const TraceField *f)
{
  size_t n = strlen(l->key);
  return n > 5 && !strcmp(l->key + n - 5, " area") && strcmp(f->name, "samples");
}

/* A pixel total that sums the sampled fields: it gets their allowance. */
static bool pixel_total(const TraceLine *l)
{
  static const char *const keys[] = {"ambient", "diffuse", "specular", "colour", "byte"};
  for (size_t k = 0; k < sizeof keys / sizeof *keys; k++)
    if (l->depth == 0 && !strcmp(l->key, keys[k]))
      return true;
  return false;
}

/* The first field of b that differs from a's, -1 when none; -2 when the
 * lines are not the same quantity (key, depth or field names). */
static int differs(const TraceLine *a, const TraceLine *b, Tolerance tol)
{
  bool samples = is_sample(a) && is_sample(b);
  if (a->depth != b->depth || (!samples && strcmp(a->key, b->key)) || a->n_fields != b->n_fields)
    return -2;
  for (int k = 0; k < a->n_fields; k++) {
    const TraceField *fa = &a->f[k], *fb = &b->f[k];
    if (strcmp(fa->name, fb->name))
      return -2;
    if (fa->n != fb->n || (fa->n == 0 && strcmp(fa->word, fb->word)))
      return k;
    if (sampled_field(a, fa))
      continue;
    /* The exported bytes may move by one code where the floats are within
     * tolerance of a rounding boundary. */
    bool byte = !strcmp(a->key, "byte");
    double slack = byte ? 1.0 : 0.0;
    for (int c = 0; c < fa->n; c++) {
      double x = fa->v[c], y = fb->v[c];
      double allowed = fmax(slack, tol.abs + tol.rel * fmax(fabs(x), fabs(y)));
      if (pixel_total(a))
        allowed += (byte ? 255.0 : 1.0) * tol.extra[c];
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

/* An area light's sampled field over a run of camera samples: sums and
 * sums of squares per channel, side 0 the reference, 1 the student's. */
enum { STATS = 32, RUN = 4096 };
typedef struct Stat {
  const TraceLine *line; /* the first reference line it appears on */
  int at;                /* that line's index */
  const char *field;
  int n, m[2], pairs;
  double sum[2][3], sq[2][3];
  double dsum[3], dsq[3]; /* the differences of matched camera samples */
} Stat;

typedef struct Stats {
  Stat s[STATS];
  int n;
} Stats;

static void stats_add(Stats *st, int side, const TraceLine *l, int at)
{
  for (int k = 0; k < l->n_fields; k++) {
    const TraceField *f = &l->f[k];
    if (!sampled_field(l, f) || f->n == 0)
      continue;
    Stat *x = NULL;
    for (int q = 0; q < st->n && !x; q++)
      if (!strcmp(st->s[q].line->key, l->key) && !strcmp(st->s[q].field, f->name))
        x = &st->s[q];
    if (!x) {
      if (st->n == STATS || side != 0)
        continue; /* a light the reference lacks parts the lines already */
      x = &st->s[st->n++];
      *x = (Stat){.line = l, .at = at, .field = f->name, .n = f->n};
    }
    x->m[side]++;
    for (int c = 0; c < f->n && c < x->n; c++) {
      x->sum[side][c] += f->v[c];
      x->sq[side][c] += f->v[c] * f->v[c];
    }
  }
}

/* The difference of a matched pair of lines (same camera sample): what the
 * sampling of the light alone moved, the pixel's own variation left out. */
static void stats_pair(Stats *st, const TraceLine *r, const TraceLine *g)
{
  for (int k = 0; k < r->n_fields && k < g->n_fields; k++) {
    const TraceField *fr = &r->f[k], *fg = &g->f[k];
    if (!sampled_field(r, fr) || fr->n == 0 || fr->n != fg->n)
      continue;
    for (int q = 0; q < st->n; q++) {
      Stat *x = &st->s[q];
      if (strcmp(x->line->key, r->key) || strcmp(x->field, fr->name))
        continue;
      x->pairs++;
      for (int c = 0; c < fr->n && c < x->n; c++) {
        double d = fg->v[c] - fr->v[c];
        x->dsum[c] += d;
        x->dsq[c] += d * d;
      }
    }
  }
}

/* Mean and variance of the mean of side `side`, channel c. */
static void stat_mean(const Stat *x, int side, int c, double *mean, double *var_mean)
{
  int m = x->m[side];
  *mean = m ? x->sum[side][c] / m : 0.0;
  double var = m > 1 ? fmax(0.0, (x->sq[side][c] - m * *mean * *mean) / (m - 1)) : 0.0;
  *var_mean = m ? var / m : 0.0;
}

/* What the means of x may differ by, channel c: 4 standard errors of the
 * differences between matched camera samples (each pair shares its camera
 * ray, so only the light's sampling moves it), the line tolerance, and one
 * for a count (shadow rays, blocked). */
static double stat_allowed(const Stat *x, int c, Tolerance tol)
{
  double m0, v0, m1, v1;
  stat_mean(x, 0, c, &m0, &v0);
  stat_mean(x, 1, c, &m1, &v1);
  int m = x->pairs;
  double dm = m ? x->dsum[c] / m : 0.0;
  double var = m > 1 ? fmax(0.0, (x->dsq[c] - m * dm * dm) / (m - 1)) : 0.0;
  bool count = x->n == 1;
  return 4.0 * sqrt(m ? var / m : 0.0) + tol.abs + tol.rel * fmax(fabs(m0), fabs(m1)) +
         (count ? 1.0 : 0.0);
}

/* The channel of x whose means differ beyond stat_allowed, -1 when none. */
static int stat_differs(const Stat *x, Tolerance tol)
{
  for (int c = 0; c < x->n; c++) {
    double m0, v0, m1, v1;
    stat_mean(x, 0, c, &m0, &v0);
    stat_mean(x, 1, c, &m1, &v1);
    if (x->m[0] != x->m[1] || !(fabs(m0 - m1) <= stat_allowed(x, c, tol)))
      return c;
  }
  return -1;
}

/* Where two traces part. kind: 0 they agree; 1 line kr of the reference
 * against line kg of the student's (field: which, -1 the whole line, -2
 * another quantity; kr or kg past the end: one line fewer); 2 the number of
 * camera samples of the run at kr (nr) and kg (ng); 3 the mean of stat. */
typedef struct Parting {
  int kind, kr, kg, field, nr, ng;
  Stat stat;
} Parting;

/* The camera samples of the run starting at line k: their first lines in
 * start[] (start[count] is the line after the run); the run's count. */
static int sample_run(const TraceLines *t, int k, int *start)
{
  int count = 0;
  while (k < t->n && is_sample(&t->line[k]) && count < RUN) {
    start[count++] = k++;
    while (k < t->n && t->line[k].depth > 0)
      k++;
  }
  start[count] = k;
  return count;
}

/* The first line of sample [a, ea) of r that differs from sample [b, eb) of
 * g (an offset), -1 when none; *field as differs says. */
static int sample_difference(const TraceLines *r, int a, int ea, const TraceLines *g, int b,
                             int eb, Tolerance tol, int *field)
{
  int na = ea - a, nb = eb - b, n = na < nb ? na : nb;
  for (int k = 0; k < n; k++)
    if ((*field = differs(&r->line[a + k], &g->line[b + k], tol)) != -1)
      return k;
  *field = -2;
  return na == nb ? -1 : n;
}

/* Compare two runs of camera samples as sets: each reference sample must
 * match a distinct sample of the student's. */
static Parting compare_runs(const TraceLines *r, const int *rs, int nr, const TraceLines *g,
                            const int *gs, int ng, Tolerance tol, Stats *st)
{
  Parting p = {.kind = 0};
  for (int i = 0; i < nr; i++)
    for (int k = rs[i]; k < rs[i + 1]; k++)
      stats_add(st, 0, &r->line[k], k);
  for (int i = 0; i < ng; i++)
    for (int k = gs[i]; k < gs[i + 1]; k++)
      stats_add(st, 1, &g->line[k], k);
  if (nr != ng)
    return (Parting){.kind = 2, .kr = rs[0], .kg = gs[0], .nr = nr, .ng = ng};
  static bool used[RUN];
  memset(used, 0, sizeof used);
  for (int i = 0; i < nr; i++) {
    int field, match = -1;
    if (!used[i] && sample_difference(r, rs[i], rs[i + 1], g, gs[i], gs[i + 1], tol, &field) < 0)
      match = i;
    for (int j = 0; j < ng && match < 0; j++)
      if (!used[j] && sample_difference(r, rs[i], rs[i + 1], g, gs[j], gs[j + 1], tol, &field) < 0)
        match = j;
    if (match >= 0) {
      used[match] = true;
      for (int k = 0; k < rs[i + 1] - rs[i]; k++)
        stats_pair(st, &r->line[rs[i] + k], &g->line[gs[match] + k]);
      continue;
    }
    /* None matches: show it against the student's sample in its place, or
     * the first one left. */
    int j = used[i] ? 0 : i;
    while (used[j])
      j++;
    int k = sample_difference(r, rs[i], rs[i + 1], g, gs[j], gs[j + 1], tol, &field);
    return (Parting){.kind = 1, .kr = rs[i] + k, .kg = gs[j] + k, .field = field};
  }
  return p;
}

/* Where `got` parts from `ref`: lines in order, runs of camera samples as
 * sets, area lights' sampled fields as means. */
static Parting compare(const TraceFile *ref, const TraceFile *got, Tolerance tol)
{
  const TraceLines *r = &ref->lines, *g = &got->lines;
  static int rs[RUN + 1], gs[RUN + 1];
  Stats st = {.n = 0};
  int kr = 0, kg = 0;
  while (kr < r->n && kg < g->n) {
    if (is_sample(&r->line[kr]) && is_sample(&g->line[kg])) {
      int nr = sample_run(r, kr, rs), ng = sample_run(g, kg, gs);
      Parting p = compare_runs(r, rs, nr, g, gs, ng, tol, &st);
      if (p.kind)
        return p;
      for (int q = 0; q < st.n; q++)
        if (stat_differs(&st.s[q], tol) >= 0)
          return (Parting){.kind = 3, .kr = st.s[q].at, .stat = st.s[q]};
      /* The pixel's totals get what the sampled means may differ by. */
      for (int q = 0; q < st.n; q++)
        if (st.s[q].n == 3)
          for (int c = 0; c < 3; c++)
            tol.extra[c] += stat_allowed(&st.s[q], c, tol);
      st.n = 0;
      kr = rs[nr], kg = gs[ng];
      continue;
    }
    int field = differs(&r->line[kr], &g->line[kg], tol);
    if (field != -1)
      return (Parting){.kind = 1, .kr = kr, .kg = kg, .field = field};
    kr++, kg++;
  }
  if (kr < r->n || kg < g->n)
    return (Parting){.kind = 1, .kr = kr, .kg = kg, .field = -2};
  return (Parting){.kind = 0};
}

/* Line kr of the reference and its parents (the enclosing lines). */
static void where(const TraceFile *ref, int kr)
{
  const TraceLine *at = &ref->lines.line[kr];
  int parents[32], n = 0;
  for (int d = at->depth - 1, j = kr - 1; d >= 0 && j >= 0 && n < 32; j--)
    if (ref->lines.line[j].depth == d) {
      parents[n++] = j;
      d--;
    }
  while (n-- > 0) {
    char text[TEXT];
    trace_line_text(&ref->lines.line[parents[n]], text, sizeof text);
    printf("            %s\n", text);
  }
}

static void explain(const TraceFile *ref, const TraceFile *got, Parting p, Tolerance tol)
{
  const TraceLines *r = &ref->lines, *g = &got->lines;
  if (p.kind == 2) {
    printf("  the pixel's camera samples (line %d of %d on) are compared as a set, in any "
           "order:\n  expected  %d camera samples\n  got       %d\n", p.kr + 1, r->n, p.nr,
           p.ng);
    printf("  read %s\n", r->line[p.kr].doc);
    return;
  }
  if (p.kind == 3) {
    const Stat *x = &p.stat;
    int c = stat_differs(x, tol);
    printf("  line %d of %d: an area light's samples, compared as the mean over the pixel's "
           "%d camera samples (another valid sampling of the light moves each one, not "
           "their mean):\n", p.kr + 1, r->n, x->m[0]);
    where(ref, p.kr);
    printf("            %s\n", x->line->key);
    for (int side = 0; side < 2; side++) {
      printf("  %-9s mean %s = (", side ? "got" : "expected", x->field);
      for (int k = 0; k < x->n; k++) {
        double m, v;
        stat_mean(x, side, k, &m, &v);
        printf("%s%g", k ? ", " : "", m);
      }
      printf(")\n");
    }
    printf("  (means agree when within 4 standard errors of the differences between the "
           "same camera samples, here %g in channel %d)\n", stat_allowed(x, c < 0 ? 0 : c, tol),
           c + 1);
    printf("  read %s\n", x->line->doc);
    return;
  }
  bool past_r = p.kr >= r->n, past_g = p.kg >= g->n;
  const TraceLine *at = past_r ? &g->line[p.kg] : &r->line[p.kr];
  printf("  line %d of %d differs; the lines above it agree%s. Where it is:\n", p.kr + 1, r->n,
         is_sample(&r->line[past_r ? r->n - 1 : p.kr]) || at->depth > 0
             ? " (camera samples compared as a set, in any order)" : "");
  if (!past_r)
    where(ref, p.kr);
  if (past_r || past_g) {
    printf(past_g ? "  expected  one more line:\n" : "  got       one line more:\n");
    show("", at, -1);
  } else {
    show("expected", &r->line[p.kr], p.field < 0 ? -1 : p.field);
    show("got", &g->line[p.kg], p.field < 0 ? -1 : p.field);
    if (p.field >= 0)
      printf("  (numbers agree when within %g relative or %g absolute)\n", tol.rel, tol.abs);
  }
  printf("  read %s\n", at->doc);
}

int main(int argc, char **argv)
{
  Tolerance tol = {1e-4, 1e-6, {0, 0, 0}};
  int a = 1;
  if (argc > 3 && !strcmp(argv[1], "--tol")) {
    tol = (Tolerance){atof(argv[2]), atof(argv[3]), {0, 0, 0}};
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
  Parting p = compare(&ref, &got, tol);
  if (!p.kind) {
    printf("PASS  %s: %s (%d lines agree)\n", cmd, what, ref.lines.n);
  } else {
    printf("FAIL  %s: %s\n", cmd, what);
    explain(&ref, &got, p, tol);
  }
  trace_lines_free(&ref.lines);
  trace_lines_free(&got.lines);
  return p.kind ? 1 : 0;
}
