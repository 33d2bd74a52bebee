/* The recorder behind --trace and --aov (common/app/trace_record.h): the
 * camera rays' hits the table saw, and each light of a lit hit shaded once
 * more by the step's own functions (shade_incident, shade_area,
 * shade_phong_light), its shadow rays recorded under it, turned into the
 * lines of a trace or the sums of an --aov. README.md, "For students";
 * docs/tracing.md. */
#include "app/trace_record.h"

#include "area_light.h"
#include "phong.h"
#include "shadow.h"

static const char *const TERM_NAMES[] = {
    [TERM_AMBIENT] = "ambient", [TERM_DIFFUSE] = "diffuse", [TERM_SPECULAR] = "specular"};
_Static_assert(sizeof TERM_NAMES / sizeof *TERM_NAMES == TERM_COUNT,
               "TERM_NAMES: one name per TraceTerm");

const char *trace_term_name(TraceTerm term)
{
  return TERM_NAMES[term];
}

void trace_flush_rays(Trace *t, int depth)
{
  for (int k = 0; k < t->rays.n; k++) {
    t->rays.line[k].depth = depth;
    trace_lines_push(&t->lines, &t->rays.line[k]);
  }
  t->rays.n = t->rays_blocked = 0;
}

static void sum_hit(Trace *t, const Hit *hit)
{
  vec3s zero = glms_vec3_zero();
  film_accum_add(&t->normal, hit ? glms_vec3_scale(glms_vec3_adds(hit->n, 1.0f), 0.5f) : zero);
  if (hit) /* the depth is the mean over the rays that hit */
    film_accum_add(&t->depth, glms_vec3_broadcast(hit->t));
  film_accum_add(&t->albedo, hit && hit->material >= 0
                                 ? t->plain.materials[hit->material].diffuse : zero);
}

void trace_on_hit(Trace *t, const Hit *hit)
{
  t->lit = hit && hit->material >= 0;
  t->light_shape = hit ? hit->light : -1;
  t->pending = t->lit;
  if (hit)
    t->hit = *hit;
  if (t->mode == TRACE_AOV)
    sum_hit(t, hit);
  if (t->mode != TRACE_RECORD || t->compact || !t->lines.n || !hit)
    return;
  TraceLine *line = &t->lines.line[t->lines.n - 1]; /* the closest hit line */
  trace_num(line, "t", hit->t);
  trace_vec(line, "p", hit->p);
  trace_vec(line, "n", hit->n);
  trace_word(line, "backface", hit->backface ? "yes" : "no");
}

/* The light's diffuse and specular terms (c[0], c[1]), as fields or lines
 * under it. */
static void light_terms(Trace *t, TraceLine *line, const vec3s c[2], int depth)
{
  for (int term = TERM_DIFFUSE; term <= TERM_SPECULAR; term++) {
    const char *name = trace_term_name((TraceTerm)term);
    TraceLine *to = t->compact ? line : trace_add(&t->lines, depth, name, TRACE_DOC_LIGHT);
    trace_vec(to, t->compact ? name : "rgb", c[term - TERM_DIFFUSE]);
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

static void on_light(Trace *t, int k, vec3s li, vec3s l, const vec3s c[2])
{
  char key[40];
  snprintf(key, sizeof key, "light %d %s", k, light_type(&t->plain.lights[k]));
  int depth = t->compact, at = t->lines.n;
  TraceLine *line = trace_add(&t->lines, depth, key, TRACE_DOC_LIGHT);
  trace_vec(line, "l", l);
  trace_num(line, "n.l", glms_vec3_dot(t->hit.n, l));
  /* The shadow ray before L_i (zero when it is blocked): a wrong shadow ray
   * is the first line that differs, not its consequence. */
  if (t->compact) { /* its answer on the same line */
    const TraceLine *ray = t->rays.n ? &t->rays.line[t->rays.n - 1] : NULL;
    trace_word(line, "occluder", ray ? ray->f[ray->n_fields - 1].word : "no ray");
    trace_vec(line, "L_i", li);
    t->rays.n = t->rays_blocked = 0;
  } else {
    trace_flush_rays(t, depth + 1);
    trace_vec(trace_add(&t->lines, depth + 1, "L_i", TRACE_DOC_LIGHT), "rgb", li);
  }
  light_terms(t, at < t->lines.n ? &t->lines.line[at] : NULL, c, depth + 1);
}

static void on_area(Trace *t, int k, const vec3s c[2])
{
  char key[40];
  snprintf(key, sizeof key, "light %d area", k);
  int depth = t->compact;
  TraceLine *line = trace_add(&t->lines, depth, key, TRACE_DOC_AREA);
  trace_num(line, "samples", t->plain.light_samples);
  trace_num(line, "shadow rays", t->rays.n);
  trace_num(line, "blocked", t->rays_blocked);
  light_terms(t, line, c, depth + 1);
  trace_flush_rays(t, depth + 1);
}

/* Light k at the last camera ray's hit, seen from v: the step's functions
 * called once more on the recorded scene (its shadow rays become this
 * light's), then on the scenes whose materials keep one term. */
static void replay_light(Trace *t, int k, vec3s v)
{
  const Light *light = &t->plain.lights[k];
  const Hit *hit = &t->hit;
  vec3s c[2];
  t->rays.n = t->rays_blocked = 0;
  t->replaying = true;
  if (light->type == LIGHT_AREA) {
    shade_area(&t->scene, k, hit, v);
    t->replaying = false;
    for (int term = TERM_DIFFUSE; term <= TERM_SPECULAR; term++)
      c[term - TERM_DIFFUSE] = shade_area(&t->masked[term], k, hit, v);
    on_area(t, k, c);
    return;
  }
  vec3s l;
  vec3s li = shade_incident(&t->scene, light, hit, &l);
  t->replaying = false;
  for (int term = TERM_DIFFUSE; term <= TERM_SPECULAR; term++)
    c[term - TERM_DIFFUSE] =
        shade_phong_light(&t->materials[term][hit->material], hit, v, li, l);
  on_light(t, k, li, l, c);
}

void trace_end_sample(Trace *t)
{
  if (t->mode != TRACE_RECORD || !t->pending)
    return;
  t->pending = false;
  vec3s v = glms_vec3_normalize(glms_vec3_sub(t->eye, t->hit.p));
  for (int k = 0; k < t->plain.n_lights; k++)
    replay_light(t, k, v);
}

void trace_begin_pixel(Trace *t)
{
  t->camera_next = true;
  t->replaying = t->pending = false;
  t->camera_rays = 0;
  t->lit = false;
  t->light_shape = -1;
  t->rays.n = t->rays_blocked = 0;
  t->normal = t->depth = t->albedo = (FilmAccum){0};
  t->shadow_rays = t->shadow_clear = 0;
}
