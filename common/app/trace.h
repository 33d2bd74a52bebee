/* Looking inside a render (every step from 02): `--trace X Y` records what
 * the step computes for one pixel (rays, hits, lights, terms), `--aov NAME`
 * (common/app/aov.c) draws one of those quantities for every pixel. Both run
 * the step's own functions; off, each hook below costs one branch.
 * README.md, "For students"; docs/testing.md, "Traces". */
#ifndef RT_TRACE_H
#define RT_TRACE_H

#include <stdio.h>

#include "app/render.h"
#include "film.h"

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

/* The step's shading functions the hooks call again, unrecorded, on a copy of
 * the scene whose materials keep one term: the per-term values come from the
 * student's own code. */
typedef vec3s (*TraceShadeFn)(const Scene *scene, Ray ray, RenderCtx *ctx);
typedef vec3s (*TraceLightFn)(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l);
typedef vec3s (*TraceAreaFn)(const Scene *scene, int light, const Hit *hit, vec3s v,
                             RenderCtx *ctx);

/* The Phong terms (index of Trace.terms, and --aov's order). */
typedef enum TraceTerm { TERM_AMBIENT, TERM_DIFFUSE, TERM_SPECULAR, TERM_COUNT } TraceTerm;

typedef struct Trace Trace;

/* Hooks the steps' glue code calls (outside the solution regions). Each one
 * is a single branch on ctx->trace, NULL unless --trace or --aov is given;
 * the work behind it is never inlined into the render (cold: out of the way
 * of the hot path; inlined, it made step 05 about 12 % slower). */
#define TRACE_COLD __attribute__((cold, noinline))
TRACE_COLD void trace_ray_(RenderCtx *ctx, const Scene *scene, Ray ray, TraceShadeFn shade);
TRACE_COLD void trace_light_(RenderCtx *ctx, const Scene *scene, int k, const Hit *hit, vec3s v,
                  vec3s li, vec3s l, TraceLightFn phong_light);
TRACE_COLD void trace_area_(RenderCtx *ctx, const Scene *scene, int k, const Hit *hit, vec3s v,
                 TraceAreaFn area);

/* A camera ray about to be shaded by `shade` (the step's shade_trace). */
static inline void trace_ray(RenderCtx *ctx, const Scene *scene, Ray ray, TraceShadeFn shade)
{
  if (__builtin_expect(ctx->trace != NULL, 0))
    trace_ray_(ctx, scene, ray, shade);
}

/* Light k's incident radiance li from the unit direction l at the hit, seen
 * from v, about to go through `phong_light` (the step's shade_phong_light). */
static inline void trace_light(RenderCtx *ctx, const Scene *scene, int k, const Hit *hit,
                               vec3s v, vec3s li, vec3s l, TraceLightFn phong_light)
{
  if (__builtin_expect(ctx->trace != NULL, 0))
    trace_light_(ctx, scene, k, hit, v, li, l, phong_light);
}

/* Area light k about to be sampled at the hit by `area` (the step's shade_area). */
static inline void trace_area(RenderCtx *ctx, const Scene *scene, int k, const Hit *hit,
                              vec3s v, TraceAreaFn area)
{
  if (__builtin_expect(ctx->trace != NULL, 0))
    trace_area_(ctx, scene, k, hit, v, area);
}

/* What --trace asks for. */
typedef struct TraceRequest {
  const char *step;    /* "05-shadows" */
  unsigned features;   /* the step's SceneFeature bits */
  RenderPixelFn pixel; /* the step's pixel function */
  int x, y;            /* pixel, x from the left, y from the top */
  Tonemap tonemap;
  bool json;           /* JSON lines instead of indented text */
  const char *args;    /* the other options of the command line (JSON header) */
} TraceRequest;

/* Render pixel (x, y) alone through req->pixel, recording every step, and
 * print the trace to `out`. False (one line printed) when (x, y) is outside
 * the film or memory runs out. */
bool trace_pixel(const Scene *scene, const RenderSettings *set, const TraceRequest *req,
                 FILE *out);

/* The text of one line as --trace prints it, indented, without a newline. */
void trace_line_text(const TraceLine *line, char *buf, size_t size);

/* Print lines as indented text, or as the JSON lines of a trace file. */
void trace_lines_print(const TraceLines *lines, bool json, FILE *out);

/* Parse one JSON line written by trace_lines_print; false when it is not one. */
bool trace_line_parse(const char *text, TraceLine *line);

/* Append a copy of `line`; false when out of memory. */
bool trace_lines_push(TraceLines *lines, const TraceLine *line);
void trace_lines_free(TraceLines *lines);

#endif
