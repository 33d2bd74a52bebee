/* The recorder behind --trace and --aov (common/app/trace_record.h): what
 * the steps' hooks reported (the camera ray's hit, each light's l, n.l, L_i
 * and term), read at each scene query and after the pixel, turned into the
 * lines of a trace or the sums of an --aov. README.md, "For students";
 * docs/tracing.md. */
#include "app/trace_record.h"

#include <stdlib.h>

static const char *const TERM_NAMES[] = {
    [TERM_AMBIENT] = "ambient", [TERM_DIFFUSE] = "diffuse", [TERM_SPECULAR] = "specular"};
_Static_assert(sizeof TERM_NAMES / sizeof *TERM_NAMES == TERM_COUNT,
               "TERM_NAMES: one name per TraceTerm");

const char *trace_term_name(TraceTerm term)
{
  return TERM_NAMES[term];
}

/* ---------------------------------------------------------------- hooks */

_Thread_local TraceEvents *trace_term_events;

/* Light event e's term: shade_phong_light called once more with the
 * arguments trace_term kept (nothing reported while it runs). */
static void light_term(TraceEvent *e)
{
  if (e->kind != TRACE_EVENT_LIGHT || !e->m)
    return;
  TraceEvents *ev = trace_term_events;
  trace_term_events = NULL;
  e->c = e->term(e->m, &e->hit, e->v, e->li, e->l);
  trace_term_events = ev;
}

void trace_flush_rays(Trace *t, int depth)
{
  for (int k = 0; k < t->rays.n; k++) {
    t->rays.line[k].depth = depth;
    trace_lines_push(&t->lines, &t->rays.line[k]);
  }
  t->rays.n = t->rays_blocked = 0;
}

static void on_hit(Trace *t, const TraceEvent *e)
{
  t->lit = e->inst->material >= 0;
  t->light_shape = e->inst->light;
  t->n = e->n;
  if (t->mode == TRACE_AOV)
    trace_sum_hit(t, e);
  if (t->mode != TRACE_RECORD || t->compact || !t->lines.n)
    return;
  TraceLine *line = &t->lines.line[t->lines.n - 1]; /* the closest hit line */
  trace_num(line, "t", e->t);
  trace_vec(line, "p", e->p);
  trace_vec(line, "n", e->n);
  trace_word(line, "backface", e->flag ? "yes" : "no");
}

/* Light k's term in camera sample `sample` from the run on materials keeping
 * `term` (each capture used once); false when that run had no such term. */
static bool captured(Trace *t, int term, uint32_t sample, int k, vec3s *c)
{
  for (int e = 0; e < t->n_captured[term]; e++) {
    TraceCaptured *cap = &t->captured[term][e];
    if (!cap->used && cap->sample == sample && cap->light == k) {
      cap->used = true;
      *c = cap->c;
      return true;
    }
  }
  return false;
}

static void capture(Trace *t, uint32_t sample, int k, vec3s c)
{
  int term = t->term, n = t->n_captured[term];
  if (n == t->cap_captured[term]) {
    int cap = n ? 2 * n : 16;
    TraceCaptured *bigger = realloc(t->captured[term], (size_t)cap * sizeof *bigger);
    if (!bigger)
      return;
    t->captured[term] = bigger;
    t->cap_captured[term] = cap;
  }
  t->captured[term][n] = (TraceCaptured){sample, k, false, c};
  t->n_captured[term] = n + 1;
}

/* A light event's term for the capture of its material term. A lit light
 * (n.l > 0, L_i not zero) whose term shade_phong_light never reported
 * (no arguments kept by trace_term) is captured as NaN, and its lines say
 * so: shade_phong computed that light's term some other way. */
static void capture_event(Trace *t, const TraceEvent *e)
{
  bool lit = e->kind == TRACE_EVENT_LIGHT && glms_vec3_dot(t->n, e->l) > 0.0f &&
             !vec_is_zero(e->li);
  capture(t, e->sample, e->light, lit && !e->m ? glms_vec3_broadcast(NAN) : e->c);
}

/* The light's diffuse and specular terms, as fields or lines under it. */
static void light_terms(Trace *t, TraceLine *line, const TraceEvent *e, int depth)
{
  for (int term = TERM_DIFFUSE; term <= TERM_SPECULAR; term++) {
    const char *name = trace_term_name((TraceTerm)term);
    vec3s c;
    TraceLine *to = t->compact ? line : trace_add(&t->lines, depth, name, TRACE_DOC_LIGHT);
    const char *field = t->compact ? name : "rgb";
    bool got = captured(t, term, e->sample, e->light, &c);
    if (got && isnan(c.x)) /* see capture_event */
      trace_word(to, field, "not reported: shade_phong_light was not called for this light");
    else if (got)
      trace_vec(to, field, c);
    else
      trace_word(to, field, "not traced with this term alone");
  }
}

/* The light's kind as its statement names it (a switch: -Wswitch fails the
 * build on a LightType without a case). */
static const char *light_type(const Light *light)
{
  switch (light->type) {
  case LIGHT_POINT: return "point";
  case LIGHT_DIRECTIONAL: return "directional";
  case LIGHT_AREA: return "area";
  }
  return "?";
}

static void on_light(Trace *t, const TraceEvent *e)
{
  char key[24];
  snprintf(key, sizeof key, "light %d %s", e->light, light_type(&t->plain.lights[e->light]));
  int depth = t->compact, at = t->lines.n;
  TraceLine *line = trace_add(&t->lines, depth, key, TRACE_DOC_LIGHT);
  trace_vec(line, "l", e->l);
  trace_num(line, "n.l", glms_vec3_dot(t->n, e->l));
  /* The shadow ray before L_i (zero when it is blocked): a wrong shadow ray
   * is the first line that differs, not its consequence. */
  if (t->compact) { /* its answer on the same line */
    const TraceLine *ray = t->rays.n ? &t->rays.line[t->rays.n - 1] : NULL;
    trace_word(line, "occluder", ray ? ray->f[ray->n_fields - 1].word : "no ray");
    trace_vec(line, "L_i", e->li);
    t->rays.n = t->rays_blocked = 0;
  } else {
    trace_flush_rays(t, depth + 1);
    trace_vec(trace_add(&t->lines, depth + 1, "L_i", TRACE_DOC_LIGHT), "rgb", e->li);
  }
  light_terms(t, at < t->lines.n ? &t->lines.line[at] : NULL, e, depth + 1);
}

static void on_area(Trace *t, const TraceEvent *e)
{
  char key[24];
  snprintf(key, sizeof key, "light %d area", e->light);
  int depth = t->compact;
  TraceLine *line = trace_add(&t->lines, depth, key, TRACE_DOC_AREA);
  trace_num(line, "samples", t->plain.light_samples);
  if (e->flag) /* the renderer proved nothing can block the light */
    trace_word(line, "shadow rays", "none needed (shadow-volume test)");
  else
    trace_num(line, "shadow rays", t->rays.n);
  trace_num(line, "blocked", t->rays_blocked);
  light_terms(t, line, e, depth + 1);
  trace_flush_rays(t, depth + 1);
}

void trace_drain(Trace *t)
{
  for (int k = 0; k < t->events.n; k++) {
    TraceEvent *e = &t->events.e[k];
    light_term(e);
    if (e->kind == TRACE_EVENT_HIT)
      on_hit(t, e);
    else if (t->mode == TRACE_CAPTURE)
      capture_event(t, e);
    else if (t->mode == TRACE_AOV && e->kind == TRACE_EVENT_AREA && e->flag) {
      t->shadow_rays += t->plain.light_samples; /* no shadow ray: all clear */
      t->shadow_clear += t->plain.light_samples;
    } else if (t->mode == TRACE_RECORD)
      (e->kind == TRACE_EVENT_LIGHT ? on_light : on_area)(t, e);
  }
  if (t->events.dropped && t->mode == TRACE_RECORD)
    trace_num(trace_add(&t->lines, 0, "not shown", TRACE_DOC_HIT), "events",
              t->events.dropped);
  t->events.n = t->events.dropped = 0;
}

void trace_sum_hit(Trace *t, const TraceEvent *hit)
{
  vec3s zero = glms_vec3_zero();
  film_accum_add(&t->normal, hit ? glms_vec3_scale(glms_vec3_adds(hit->n, 1.0f), 0.5f) : zero);
  if (hit) /* the depth is the mean over the rays that hit */
    film_accum_add(&t->depth, glms_vec3_broadcast(hit->t));
  film_accum_add(&t->albedo, hit && hit->inst->material >= 0
                                 ? t->plain.materials[hit->inst->material].diffuse : zero);
}

void trace_begin_pixel(Trace *t)
{
  t->camera_next = true;
  t->camera_rays = 0;
  t->lit = false;
  t->light_shape = -1;
  t->normal = t->depth = t->albedo = (FilmAccum){0};
  t->shadow_rays = t->shadow_clear = 0;
}
