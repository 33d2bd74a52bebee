/* The shape conformance suite: every shape of the registry (SHAPE_REGISTRY,
 * common/shapes.h) is checked here without a line of its own. Each is built
 * by its name_example at scales from 1e-4 to 1e5 and three orientations,
 * and rays are aimed at points of its exact surface (name_surface, long
 * double). The reference hit of each float ray is found in long double
 * (Newton's method on the surface's parameters), and:
 *   - name_hit_t hits it from the front and from behind, at the reference t,
 *     grazing rays (d . n = 2e-3) included, and misses it when tmax stops
 *     short of it;
 *   - name_hit_t misses rays leaving the surface, rays parallel to it just
 *     above it, and rays aimed just past its edge;
 *   - name_hit_fill gives n unit, facing the ray, along the surface's normal,
 *     backface as the side says, p within p_err |n|_1 of the exact surface
 *     (the box of possible exact points reaches it), p inside name_bounds;
 *   - a ray leaving a hit, started 2 p_err |n|_1 off the surface as
 *     ray_spawn starts it, never meets the shape again near its start (no
 *     self-shadowing);
 *   - the scene's dispatch (scene_instance_hit_t, scene_instance_bounds,
 *     scene_shape_name) calls the shape's own functions.
 * A failure names the shape's function and its doc (the registry's DOC);
 * docs/extending.md, "The conformance suite", says what each check asks. */
#include "check.h"

#include <float.h>

#include "scene.h"
#include "scene_index.h"
#include "surface.h"

/* ---------------------------------------------------------------- the kinds */

/* A shape of any kind, by value. */
#define ANY_MEMBER_(NAME, name, Type, STORE, DOC) Type name;
typedef union AnyShape {
  SHAPE_REGISTRY(ANY_MEMBER_)
} AnyShape;
#undef ANY_MEMBER_

/* One kind's functions, called through an AnyShape. */
typedef struct Kind {
  ShapeType type;
  const char *name, *doc;
  const char *hit_t_name, *fill_name, *bounds_name;
  void (*example)(AnyShape *s, vec3s at, float size, vec3s axis);
  float (*hit_t)(const AnyShape *s, Ray r, float tmax);
  void (*hit_fill)(const AnyShape *s, Ray r, float t, Hit *hit);
  Box (*bounds)(const AnyShape *s);
  bool (*surface)(const AnyShape *s, long double u, long double v, SurfacePoint *sp);
  void (*instance)(const AnyShape *s, Instance *inst);
} Kind;

#define INST_SET_INPLACE(inst, name, s) ((inst)->name = (s)->name)
#define INST_SET_KEPT(inst, name, s) ((inst)->name = &(s)->name)
#define ADAPT_(NAME, name, Type, STORE, DOC)                                              \
  static void name##_example_(AnyShape *s, vec3s at, float size, vec3s axis)              \
  {                                                                                       \
    s->name = name##_example(at, size, axis);                                             \
  }                                                                                       \
  static float name##_hit_t_(const AnyShape *s, Ray r, float tmax)                        \
  {                                                                                       \
    return name##_hit_t(&s->name, r, tmax);                                               \
  }                                                                                       \
  static void name##_hit_fill_(const AnyShape *s, Ray r, float t, Hit *hit)               \
  {                                                                                       \
    name##_hit_fill(&s->name, r, t, hit);                                                 \
  }                                                                                       \
  static Box name##_bounds_(const AnyShape *s)                                            \
  {                                                                                       \
    return name##_bounds(&s->name);                                                       \
  }                                                                                       \
  static bool name##_surface_(const AnyShape *s, long double u, long double v,            \
                              SurfacePoint *sp)                                           \
  {                                                                                       \
    return name##_surface(&s->name, u, v, sp);                                            \
  }                                                                                       \
  static void name##_instance_(const AnyShape *s, Instance *inst)                         \
  {                                                                                       \
    *inst = (Instance){.shape = SHAPE_##NAME, .material = 0, .light = -1};                \
    INST_SET_##STORE(inst, name, s);                                                      \
  }
SHAPE_REGISTRY(ADAPT_)
#undef ADAPT_

#define KIND_(NAME, name, Type, STORE, DOC)                                               \
  [SHAPE_##NAME] = {SHAPE_##NAME, #name, DOC, #name "_hit_t", #name "_hit_fill",          \
                    #name "_bounds", name##_example_, name##_hit_t_, name##_hit_fill_,    \
                    name##_bounds_, name##_surface_, name##_instance_},
static const Kind KINDS[SHAPE_COUNT] = {SHAPE_REGISTRY(KIND_)};
#undef KIND_

/* ---------------------------------------------------------------- the cases */

/* Sizes and places from 1e-4 to 1e5: a tiny shape at the origin and off it,
 * unit shapes near and far, a shape of 100 at 1e5, huge shapes. */
static const struct Scale {
  float size;
  float at[3];
} SCALES[] = {
    {1e-4f, {0, 0, 0}},    {1e-4f, {3e-4f, -2e-4f, 1e-4f}}, {1, {0.5f, -0.25f, 2}},
    {1, {1000, -500, 200}}, {100, {1e5f, 2e4f, -3e4f}},      {1e5f, {0, 0, 0}},
    {1e5f, {-1e5f, 5e4f, 1e5f}},
};
enum { N_SCALES = sizeof SCALES / sizeof *SCALES };

/* Orientations: along an axis (a flat shape's hits then snap exactly), in a
 * coordinate plane, and general. */
static const float AXES[][3] = {
    {0, 0, 1}, {0.6f, 0, 0.8f}, {0.26726124f, -0.53452248f, 0.80178373f}};
enum { N_AXES = sizeof AXES / sizeof *AXES };

/* Surface parameters aimed at (inside every shape: u, v in (0.1, 0.8)). */
static const long double US[] = {0.13L, 0.37L, 0.61L, 0.79L};
static const long double VS[] = {0.17L, 0.42L, 0.68L, 0.79L};

/* d . n of the rays' directions with the surface normal, from head-on to
 * grazing. */
static const long double COSINES[] = {1.0L, 0.8L, 0.35L, 0.05L, 2e-3L};
enum { N_COSINES = sizeof COSINES / sizeof *COSINES };

/* One configuration: the shape, its kind, its scale and its words. */
typedef struct Case {
  const Kind *k;
  AnyShape s;
  float size;
  vec3s at, axis;
  char what[160]; /* "a disc of size 1 at (0.5, -0.25, 2) facing (0.6, 0, 0.8)" */
} Case;

static void case_make(Case *c, const Kind *k, int scale, int axis)
{
  c->k = k;
  c->size = SCALES[scale].size;
  c->at = vec_make(SCALES[scale].at[0], SCALES[scale].at[1], SCALES[scale].at[2]);
  c->axis = vec_make(AXES[axis][0], AXES[axis][1], AXES[axis][2]);
  k->example(&c->s, c->at, c->size, c->axis);
  snprintf(c->what, sizeof c->what, "%s %s of size %g at (%g, %g, %g) facing (%g, %g, %g)",
           strchr("aeiou", k->name[0]) ? "an" : "a", k->name, c->size, c->at.x, c->at.y,
           c->at.z, c->axis.x, c->axis.y, c->axis.z);
}

/* ---------------------------------------------------------------- long double */

typedef long double L3[3];

static void l3_of(vec3s v, L3 out)
{
  surface_ld(v, out);
}

static long double l3_max_abs(const L3 v)
{
  return fmaxl(fabsl(v[0]), fmaxl(fabsl(v[1]), fabsl(v[2])));
}

/* The float ray from o along d (d rounded, then made unit as a ray's is). */
static Ray ray_of(const L3 o, const L3 d)
{
  Ray r = {.o = vec_make((float)o[0], (float)o[1], (float)o[2]),
           .d = vec_normalize(vec_make((float)d[0], (float)d[1], (float)d[2]))};
  return r;
}

/* The reference hit of the float ray r near the surface point at (u, v):
 * the parameters and t where surface(u, v) = o + t d, by Newton's method in
 * long double from (u, v, t0) (derivatives by central differences). False
 * when it does not converge. */
static bool reference_hit(const Case *c, Ray r, long double u, long double v, long double t0,
                          SurfacePoint *at, long double *t, bool *inside)
{
  L3 o, d;
  l3_of(r.o, o);
  l3_of(r.d, d);
  long double x[3] = {u, v, t0}, mag = fmaxl(l3_max_abs(o), fabsl(t0)), res = INFINITY;
  SurfacePoint s;
  for (int it = 0; it < 16; it++) {
    SurfacePoint su[2], sv[2];
    const long double h = 1e-7L;
    c->k->surface(&c->s, x[0], x[1], &s);
    c->k->surface(&c->s, x[0] + h, x[1], &su[0]);
    c->k->surface(&c->s, x[0] - h, x[1], &su[1]);
    c->k->surface(&c->s, x[0], x[1] + h, &sv[0]);
    c->k->surface(&c->s, x[0], x[1] - h, &sv[1]);
    long double f[3], ju[3], jv[3], jt[3];
    for (int a = 0; a < 3; a++) {
      f[a] = s.p[a] - (o[a] + x[2] * d[a]);
      ju[a] = (su[0].p[a] - su[1].p[a]) / (2 * h);
      jv[a] = (sv[0].p[a] - sv[1].p[a]) / (2 * h);
      jt[a] = -d[a];
    }
    res = l3_max_abs(f);
    /* Solve [ju jv jt] dx = -f by Cramer's rule. */
    L3 c0, c1, c2;
    surface_cross(jv, jt, c0);
    long double det = surface_dot(ju, c0);
    if (!(fabsl(det) > 0))
      return false;
    surface_cross(jt, ju, c1);
    surface_cross(ju, jv, c2);
    x[0] -= surface_dot(f, c0) / det;
    x[1] -= surface_dot(f, c1) / det;
    x[2] -= surface_dot(f, c2) / det;
  }
  /* Converged: o + t d on the surface to within 2^-48 of the magnitudes
   * (the float hits are checked to 2^-19 of them). */
  *inside = c->k->surface(&c->s, x[0], x[1], at);
  long double f = 0;
  for (int a = 0; a < 3; a++)
    f = fmaxl(f, fabsl(at->p[a] - (o[a] + x[2] * d[a])));
  (void)res;
  *t = x[2];
  return f <= 0x1p-48L * (mag + fabsl(x[2])) && *t > 0;
}

/* ---------------------------------------------------------------- checks */

typedef struct Checks {
  Check hit_t, fill, bounds, spawn, dispatch;
  int skipped, cases;
} Checks;

static Checks checks_make(const Kind *k)
{
  return (Checks){CHECK(k->hit_t_name, k->doc), CHECK(k->fill_name, k->doc),
                  CHECK(k->bounds_name, k->doc),
                  CHECK(k->fill_name, k->doc),
                  CHECK("scene_instance_hit_t",
                        "docs/extending.md, \"Adding a shape\" (the SHAPE_REGISTRY line)"),
                  0, 0};
}

static void checks_done(const Kind *k, Checks *ck)
{
  cr_log_info("%s: %d rays aimed at its surface (%d without a reference), at %d scales x %d "
              "orientations: %d checks of %s, %d of %s, %d of %s, %d of spawned rays, %d of "
              "the dispatch",
              k->name, ck->cases, ck->skipped, N_SCALES, N_AXES, ck->hit_t.cases, k->hit_t_name,
              ck->fill.cases, k->fill_name, ck->bounds.cases, k->bounds_name, ck->spawn.cases,
              ck->dispatch.cases);
  CHECK_DONE(&ck->hit_t);
  CHECK_DONE(&ck->fill);
  CHECK_DONE(&ck->bounds);
  CHECK_DONE(&ck->spawn);
  CHECK_DONE(&ck->dispatch);
  /* The suite must have tested something: a shape whose surface the
   * reference cannot follow is a shape it cannot check. */
  cr_expect(ck->skipped * 10 <= ck->cases,
            "the shape conformance suite: %d of %d rays had no long-double reference "
            "(name_surface must be smooth in u, v)\n"
            "  read docs/extending.md, \"The conformance suite\"",
            ck->skipped, ck->cases);
}

/* The ray's words: "a front ray at (u 0.13, v 0.42) of <case> (o (..), d (..),
 * d.n -0.35)". */
static const char *ray_words(char *buf, size_t size, const char *side, long double dn,
                             long double u, long double v, const Case *c, Ray r)
{
  snprintf(buf, size,
           "%s ray at (u %.2Lg, v %.2Lg) of %s (o (%.9g, %.9g, %.9g), d (%.9g, %.9g, "
           "%.9g), d.n %.3Lg)",
           side, u, v, c->what, r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, dn);
  return buf;
}

/* The hit the reference found: name_hit_t, name_hit_fill, name_bounds and
 * the spawned rays. `back`: the ray comes from behind the surface. */
static void check_hit(Checks *ck, const Case *c, Ray r, const SurfacePoint *ref, long double t_ref,
                      bool back, const char *words)
{
  const Kind *k = c->k;
  L3 o, d;
  l3_of(r.o, o);
  l3_of(r.d, d);
  long double mag = fmaxl(l3_max_abs(o), l3_max_abs(ref->p)) + c->size;
  long double adn = fabsl(surface_dot(d, ref->n));
  /* t's error, measured along the normal, within 2^-19 of the magnitudes:
   * an accurate test errs by a few ulps of them. */
  double tol_t = (double)(0x1p-19L * mag / adn);
  float t = k->hit_t(&c->s, r, INFINITY);
  CHECK_NEAR(&ck->hit_t, (double)t_ref, t, tol_t, "%s: t", words);
  if (!(fabs((double)t - (double)t_ref) <= tol_t))
    return;
  long double short_of = t_ref - 4 * (long double)tol_t;
  if (short_of > 0.5L * t_ref)
    CHECK_NEAR(&ck->hit_t, INFINITY, k->hit_t(&c->s, r, (float)short_of), 0.0,
               "%s, tmax = %.9Lg, short of the hit: a miss", words, short_of);

  Hit h;
  memset(&h, 0, sizeof h);
  k->hit_fill(&c->s, r, t, &h);
  L3 p, n;
  l3_of(h.p, p);
  l3_of(h.n, n);
  CHECK_NEAR(&ck->fill, t, h.t, 0.0, "%s: hit.t", words);
  CHECK_NEAR(&ck->fill, 1.0, (double)sqrtl(surface_dot(n, n)), 1e-6, "%s: |hit.n| (unit)", words);
  CHECK_THAT(&ck->fill, surface_dot(n, d) < 0,
             "%s: hit.n faces the ray\n  expected hit.n . d < 0\n  got      %.9Lg (hit.n "
             "(%.9g, %.9g, %.9g))",
             words, surface_dot(n, d), h.n.x, h.n.y, h.n.z);
  long double side = back ? -1 : 1, off = 0;
  for (int a = 0; a < 3; a++)
    off = fmaxl(off, fabsl(n[a] - side * ref->n[a]));
  /* The normal where p is: p may sit along the surface from the exact hit
   * (t's error), where a curved surface (curvature at most 1 / size) turns. */
  long double along = 0;
  for (int a = 0; a < 3; a++)
    along = fmaxl(along, fabsl(p[a] - ref->p[a]));
  double tol_n = (double)(1e-5L + 0x1p-18L * mag / c->size + 2 * along / c->size);
  CHECK_THAT(&ck->fill, off <= tol_n,
             "%s: hit.n along the surface's normal (long double)\n  expected (%.9Lg, "
             "%.9Lg, %.9Lg) (within %.3g)\n  got      (%.9g, %.9g, %.9g)",
             words, side * ref->n[0], side * ref->n[1], side * ref->n[2], tol_n, h.n.x, h.n.y,
             h.n.z);
  CHECK_INT(&ck->fill, back, h.backface, "%s: hit.backface", words);
  /* p_err: the box p +- p_err reaches the exact surface, which lies
   * (p - P) . n from p along the normal. */
  long double dist = fabsl((p[0] - ref->p[0]) * ref->n[0] + (p[1] - ref->p[1]) * ref->n[1] +
                           (p[2] - ref->p[2]) * ref->n[2]);
  long double reach = (long double)h.p_err * (fabsl(n[0]) + fabsl(n[1]) + fabsl(n[2]));
  CHECK_THAT(&ck->fill, dist <= reach + 0x1p-60L * mag,
             "%s: p_err bounds the distance of hit.p from the exact surface (long double)\n"
             "  expected distance <= p_err |n|_1 = %.9Lg (p_err %.9g)\n  got      "
             "distance %.9Lg",
             words, reach, h.p_err, dist);
  CHECK_THAT(&ck->fill, h.p_err <= 0x1p-16L * mag,
             "%s: p_err, a bound of a few ulps of the coordinates\n  expected at most "
             "2^-16 (|coordinates| + size) = %.9Lg\n  got      %.9g",
             words, 0x1p-16L * mag, h.p_err);
  CHECK_THAT(&ck->fill, along <= (long double)tol_t + 0x1p-18L * mag,
             "%s: hit.p at the exact hit (long double)\n  expected (%.9Lg, %.9Lg, %.9Lg) "
             "(within %.3Lg)\n  got      (%.9g, %.9g, %.9g)",
             words, ref->p[0], ref->p[1], ref->p[2], (long double)tol_t + 0x1p-18L * mag,
             h.p.x, h.p.y, h.p.z);
  Box b = k->bounds(&c->s);
  CHECK_THAT(&ck->bounds, box_holds(b, h.p),
             "%s: the hit point inside the shape's box\n  expected within (%.9g, %.9g, %.9g) "
             ".. (%.9g, %.9g, %.9g)\n  got      (%.9g, %.9g, %.9g)",
             words, b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, h.p.x, h.p.y, h.p.z);

  /* Rays leaving the hit on the side it was seen from, started as ray_spawn
   * starts them: 2 p_err |n|_1 along n (docs/05-shadows.md). */
  L3 t1, t2;
  surface_basis(n, t1, t2);
  static const long double LEAVE[] = {1.0L, 0.5L, 0.1L};
  for (int j = 0; j < 3; j++) {
    long double cs = LEAVE[j], sn = sqrtl(1 - cs * cs), w[3];
    for (int a = 0; a < 3; a++)
      w[a] = cs * n[a] + sn * (j == 1 ? t2[a] : t1[a]);
    float push = 2.0f * h.p_err * vec_sum_abs(h.n);
    Ray out = {.o = glms_vec3_add(h.p, glms_vec3_scale(h.n, push)),
               .d = vec_normalize(vec_make((float)w[0], (float)w[1], (float)w[2]))};
    float again = k->hit_t(&c->s, out, INFINITY);
    CHECK_THAT(&ck->spawn, !(again < 0.01f * c->size),
               "%s: a ray leaving its hit (d . n = %.2Lg), started 2 p_err |n|_1 = %.3g off "
               "the surface as ray_spawn starts it, must not meet the %s again at once "
               "(self-shadowing: p_err too small, or %s accepting t near 0)\n"
               "  expected no hit, or t >= %.3g\n  got      t = %.9g",
               words, cs, push, k->name, k->hit_t_name, 0.01 * c->size, again);
  }
}

/* Rays at the point (u, v): from the front and from behind, each cosine. */
static void rays_at(Checks *ck, const Case *c, long double u, long double v, int seed)
{
  SurfacePoint sp;
  if (!c->k->surface(&c->s, u, v, &sp))
    return;
  L3 t1, t2;
  surface_basis(sp.n, t1, t2);
  for (int j = 0; j < N_COSINES; j++) {
    long double cs = COSINES[j], sn = sqrtl(1 - cs * cs);
    long double az = 0.7L * (seed + 3 * j), ca = cosl(az), sa = sinl(az);
    for (int back = 0; back < 2; back++) {
      /* Toward the surface: d = -(cs n + sn t) from the front, +(...) from
       * behind; from behind start close (inside a solid, within its chord). */
      long double sgn = back ? 1 : -1, d[3], o[3];
      long double len = back ? 0.5L * c->size * cs : 2.0L * c->size;
      for (int a = 0; a < 3; a++) {
        d[a] = sgn * (cs * sp.n[a] + sn * (ca * t1[a] + sa * t2[a]));
        o[a] = sp.p[a] - len * d[a];
      }
      Ray r = ray_of(o, d);
      /* From behind, the origin must be off the surface by more than its
       * rounding (inside a solid, within its chord, is close). */
      if (back && len * cs < 0x1p-14L * (l3_max_abs(sp.p) + c->size))
        continue;
      SurfacePoint ref;
      long double t_ref;
      bool inside;
      ck->cases++;
      if (!reference_hit(c, r, u, v, len, &ref, &t_ref, &inside) || !inside) {
        ck->skipped++;
        continue;
      }
      char words[512];
      L3 dl;
      l3_of(r.d, dl);
      ray_words(words, sizeof words, back ? "a back" : "a front", surface_dot(dl, ref.n), u, v,
                c, r);
      check_hit(ck, c, r, &ref, t_ref, back, words);
    }
  }
}

/* Rays that must miss: leaving the surface, parallel to it just above it,
 * aimed just past an edge. */
static void misses(Checks *ck, const Case *c)
{
  const Kind *k = c->k;
  char words[512];
  for (int i = 0; i < 4; i++) {
    SurfacePoint sp;
    long double u = US[i], v = VS[3 - i];
    if (!k->surface(&c->s, u, v, &sp))
      continue;
    L3 t1, t2, o, d;
    surface_basis(sp.n, t1, t2);
    long double mag = l3_max_abs(sp.p) + c->size;
    /* Leaving: from 2 sizes above the point, away from it. */
    for (int a = 0; a < 3; a++) {
      o[a] = sp.p[a] + 2 * c->size * sp.n[a];
      d[a] = 0.8L * sp.n[a] + 0.6L * t1[a];
    }
    Ray r = ray_of(o, d);
    ray_words(words, sizeof words, "a leaving", 0.8L, u, v, c, r);
    CHECK_NEAR(&ck->hit_t, INFINITY, k->hit_t(&c->s, r, INFINITY), 0.0,
               "%s, going away from the surface: a miss", words);
    /* Parallel: along the tangent plane, above it by 1e-3 of the size (and
     * well above the coordinates' rounding), passing over the point. */
    long double h = 1e-3L * c->size + 0x1p-14L * mag;
    for (int a = 0; a < 3; a++) {
      d[a] = i % 2 ? t1[a] : t2[a];
      o[a] = sp.p[a] + h * sp.n[a] - 2 * c->size * d[a];
    }
    r = ray_of(o, d);
    ray_words(words, sizeof words, "a parallel", 0.0L, u, v, c, r);
    CHECK_NEAR(&ck->hit_t, INFINITY, k->hit_t(&c->s, r, 100.0f * c->size), 0.0,
               "%s, %.3Lg above the tangent plane, tmax = 100 sizes: a miss", words, h);
  }
  /* Past an edge: parameters 6 % beyond [0, 1], where the surface says it
   * is not the shape. */
  static const long double PAST[][2] = {{1.06L, 0.3L}, {-0.06L, 0.7L}, {0.3L, 1.06L},
                                        {0.7L, -0.06L}, {1.06L, 0.5L}};
  for (int i = 0; i < 5; i++) {
    SurfacePoint sp;
    long double u = PAST[i][0], v = PAST[i][1];
    if (k->surface(&c->s, u, v, &sp))
      continue; /* no edge there (a sphere, a plane) */
    L3 t1, t2, o, d;
    surface_basis(sp.n, t1, t2);
    for (int a = 0; a < 3; a++) {
      d[a] = -(0.8L * sp.n[a] + 0.6L * t2[a]);
      o[a] = sp.p[a] - 2 * c->size * d[a];
    }
    Ray r = ray_of(o, d);
    SurfacePoint ref;
    long double t_ref;
    bool inside;
    if (!reference_hit(c, r, u, v, 2 * c->size, &ref, &t_ref, &inside) || inside)
      continue;
    ray_words(words, sizeof words, "a front", -0.8L, u, v, c, r);
    CHECK_NEAR(&ck->hit_t, INFINITY, k->hit_t(&c->s, r, INFINITY), 0.0,
               "%s, 6 %% past the edge: a miss", words);
  }
}

/* The scene's dispatch calls this shape's own functions. */
static void dispatch(Checks *ck, const Case *c)
{
  const Kind *k = c->k;
  Instance inst;
  k->instance(&c->s, &inst);
  SurfacePoint sp;
  k->surface(&c->s, 0.37L, 0.42L, &sp);
  L3 o, d;
  for (int a = 0; a < 3; a++) {
    d[a] = -sp.n[a];
    o[a] = sp.p[a] + 2 * c->size * sp.n[a];
  }
  Ray r = ray_of(o, d);
  float own = k->hit_t(&c->s, r, INFINITY), via = scene_instance_hit_t(&inst, r, INFINITY);
  CHECK_THAT(&ck->dispatch, own == via || (own != own && via != via),
             "a %s instance (SHAPE_%s...): the %s's own %s\n  expected %.9g\n  got      %.9g",
             k->name, k->name, k->name, k->hit_t_name, own, via);
  Box a = k->bounds(&c->s), b = scene_instance_bounds(&inst);
  CHECK_THAT(&ck->dispatch, !memcmp(&a, &b, sizeof a),
             "scene_instance_bounds of a %s instance: its %s\n  expected min (%g, %g, %g)\n"
             "  got      min (%g, %g, %g)",
             k->name, k->bounds_name, a.min.x, a.min.y, a.min.z, b.min.x, b.min.y, b.min.z);
  CHECK_THAT(&ck->dispatch, !strcmp(scene_shape_name(k->type), k->name),
             "scene_shape_name(SHAPE_...) of a %s\n  expected \"%s\"\n  got      \"%s\"",
             k->name, k->name, scene_shape_name(k->type));
}

static void conform(const Kind *k)
{
  Checks ck = checks_make(k);
  for (int s = 0; s < N_SCALES; s++)
    for (int x = 0; x < N_AXES; x++) {
      Case c;
      case_make(&c, k, s, x);
      int seed = 0;
      for (size_t i = 0; i < sizeof US / sizeof *US; i++)
        for (size_t j = 0; j < sizeof VS / sizeof *VS; j++)
          rays_at(&ck, &c, US[i], VS[j], seed++);
      misses(&ck, &c);
      dispatch(&ck, &c);
    }
  checks_done(k, &ck);
}

/* One test per registered shape. */
#define TEST_(NAME, name, Type, STORE, DOC)                                               \
  Test(shapes, name##_conforms) { conform(&KINDS[SHAPE_##NAME]); }
SHAPE_REGISTRY(TEST_)
#undef TEST_
