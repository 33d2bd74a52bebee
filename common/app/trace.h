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
  /* LIGHT: shade_phong_light's arguments for this L_i and l (trace_term),
   * `term` the function itself (trace_incident); the recorder calls it once
   * more with them for the term. m NULL: not called for this light. */
  vec3s (*term)(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l);
  const Material *m;
  Hit hit;
  vec3s v;
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
#define TRACE_ON(ctx) ((ctx)->trace != NULL)
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

/* A light's term is reported in two halves, so that the trace follows
 * whatever shade_phong does with the step's functions: shade_incident
 * reports light k's L_i and l (trace_incident), and shade_phong_light,
 * wherever it is called from, its arguments for that L_i and l
 * (trace_term); the recorder calls shade_phong_light once more with them
 * for the term, whatever return its code takes. shade_phong_light has no
 * ctx: the events of the pixel this thread traces are in trace_term_events
 * (NULL when off). Both hooks only store: the recorder makes the call. */
extern _Thread_local struct TraceEvents *trace_term_events;

typedef vec3s (*TraceTermFn)(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l);

/* Light k's radiance li arriving from the unit direction l at the camera
 * ray's hit (shade_incident); term: the step's shade_phong_light. Returns li. */
static inline vec3s trace_incident(RenderCtx *ctx, int k, vec3s li, vec3s l, TraceTermFn term)
{
#ifndef TRACE_COMPILED_OUT
  trace_term_events = ctx->trace;
#endif
  if (TRACE_ON(ctx)) {
    TraceEvent *e = trace_slot(ctx, TRACE_EVENT_LIGHT);
    e->light = k;
    e->li = li;
    e->l = l;
    e->c = glms_vec3_zero();
    e->term = term;
    e->m = NULL;
  }
  return li;
}

/* shade_phong_light's arguments, first thing in it: kept with the light
 * trace_incident reported last with this li and l. */
static inline void trace_term(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l)
{
#ifndef TRACE_COMPILED_OUT
  TraceEvents *ev = trace_term_events;
  if (ev != NULL)
    for (int k = (ev->n < TRACE_EVENTS ? ev->n : TRACE_EVENTS + 1) - 1; k >= 0; k--) {
      TraceEvent *e = &ev->e[k];
      if (e->kind == TRACE_EVENT_LIGHT && !e->m && e->li.x == li.x && e->li.y == li.y &&
          e->li.z == li.z && e->l.x == l.x && e->l.y == l.y && e->l.z == l.z) {
        e->m = m;
        e->hit = *hit;
        e->v = v;
        break;
      }
    }
#else
  (void)m, (void)hit, (void)v, (void)li, (void)l;
#endif
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
