/* The hooks behind `--trace X Y` and `--aov NAME` (every step from 02): the
 * steps' glue code reports what it computes for a pixel (the camera ray's
 * hit, each light's l, L_i and term) here; the recorder (app/trace_record.h)
 * turns it into a pixel's trace (app/trace_pixel.h) or one quantity as a
 * picture (app/aov.h). Off, each hook costs one branch. README.md, "For
 * students"; docs/tracing.md. */
#ifndef RT_TRACE_H
#define RT_TRACE_H

#include "app/render.h"

/* What a hook reports: a camera ray's closest hit, a light's term at it. */
typedef enum TraceEventKind { TRACE_EVENT_HIT, TRACE_EVENT_LIGHT, TRACE_EVENT_AREA } TraceEventKind;

typedef struct TraceEvent {
  TraceEventKind kind;
  int light;           /* LIGHT, AREA: index into scene->lights */
  uint32_t sample;     /* ctx->sample */
  bool flag;           /* HIT: a back face; AREA: proved unblocked (no
                        * shadow ray traced) */
  const struct Instance *inst; /* HIT: the instance hit */
  float t;             /* HIT: its distance */
  vec3s p, n;          /* HIT: the hit point and normal */
  vec3s li, l, c;      /* LIGHT: L_i, toward the light, the term; AREA: c */
} TraceEvent;

/* The events reported since the recorder last read them (it does at each
 * scene query and after the pixel); the last slot takes what does not fit. */
enum { TRACE_EVENTS = 64 };
typedef struct TraceEvents {
  int n, dropped;      /* dropped: reported when the buffer was full */
  TraceEvent e[TRACE_EVENTS + 1];
} TraceEvents;

/* Hooks the steps' glue code calls (outside the solution regions), each one
 * branch on ctx->trace (NULL unless --trace or --aov is given). A hook only
 * stores the values it is given into ctx->trace, one by one, and hands back
 * its last argument: no call and no copy of a whole struct, so that the
 * render around it compiles as it would without it (docs/tracing.md,
 * "What it costs when off", measures it; make bench compares with a build
 * whose hooks are compiled out, -DTRACE_COMPILED_OUT). */
#ifdef TRACE_COMPILED_OUT /* make bench's second build (TRACE_OFF=1): no hooks */
#define TRACE_ON(ctx) ((void)(ctx), 0)
#else
#define TRACE_ON(ctx) __builtin_expect((ctx)->trace != NULL, 0)
#endif

static inline TraceEvent *trace_slot(RenderCtx *ctx, TraceEventKind kind)
{
  TraceEvents *ev = ctx->trace;
  TraceEvent *e = &ev->e[ev->n < TRACE_EVENTS ? ev->n++ : TRACE_EVENTS];
  ev->dropped += e == &ev->e[TRACE_EVENTS];
  e->kind = kind;
  e->sample = ctx->sample;
  return e;
}

/* The closest hit of a camera ray (the ray itself is in the query the
 * recorder saw). */
static inline void trace_hit(RenderCtx *ctx, const Hit *hit)
{
  if (TRACE_ON(ctx)) {
    TraceEvent *e = trace_slot(ctx, TRACE_EVENT_HIT);
    e->inst = hit->inst;
    e->t = hit->t;
    e->p = hit->p;
    e->n = hit->n;
    e->flag = hit->backface;
  }
}

/* Light k's term c for the radiance li arriving from the unit direction l at
 * the camera ray's hit; returns c. */
static inline vec3s trace_light(RenderCtx *ctx, int k, vec3s li, vec3s l, vec3s c)
{
  if (TRACE_ON(ctx)) {
    TraceEvent *e = trace_slot(ctx, TRACE_EVENT_LIGHT);
    e->light = k;
    e->li = li;
    e->l = l;
    e->c = c;
  }
  return c;
}

/* Area light k's term c at the hit (the sum over its samples); `unoccluded`
 * when the renderer proved nothing can block it. Returns c. */
static inline vec3s trace_area(RenderCtx *ctx, int k, bool unoccluded, vec3s c)
{
  if (TRACE_ON(ctx)) {
    TraceEvent *e = trace_slot(ctx, TRACE_EVENT_AREA);
    e->light = k;
    e->flag = unoccluded;
    e->c = c;
  }
  return c;
}

#endif
