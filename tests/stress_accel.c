/* The acceleration structure (docs/performance.md) against the definition of
 * the queries: closest hit = the first instance, in order, at the smallest
 * sphere_hit_t / plane_hit_t distance; any-hit = some lit shape at t < tmax.
 * The reference is that loop written out here, over random scenes and rays
 * (grazing ones included), for the flat layout and the hierarchy. */
#include "threads.h"
#include <stdlib.h>

#include "index/accel.h"
#include "index/bvh.h"
#include "check.h"
#include "rng.h"
#include "stress.h"

static float uni(Rng *g, float lo, float hi) { return lo + (hi - lo) * rng_float(g); }

/* One material, the floor y = 0 and n random spheres (some tiny, some
 * duplicates of the one before: equal distances) within `half` of the
 * origin across, instances 1 .. n; not prepared. */
static void spheres_on_floor(Scene *s, Rng *g, int n, float half)
{
  scene_init(s);
  Material m = {.name = "m", .diffuse = vec_make(0.5f, 0.5f, 0.5f)};
  cr_assert(scene_add_material(s, &m), "out of memory");
  Plane floor = plane_make(vec_make(0, 0, 0), vec_make(0, 1, 0));
  Instance pl = {.shape = SHAPE_PLANE, .plane = floor, .light = -1};
  cr_assert(scene_add_instance(s, &pl), "out of memory");
  for (int k = 0; k < n; k++) {
    Instance in = {.shape = SHAPE_SPHERE, .light = -1};
    in.sphere.center = vec_make(uni(g, -half, half), uni(g, 0, 5), uni(g, -half, half));
    in.sphere.radius = k % 7 == 0 ? 1e-3f : uni(g, 0.05f, 1.5f);
    if (k % 11 == 5)
      in.sphere = s->instances[s->n_instances - 1].sphere;
    cr_assert(scene_add_instance(s, &in), "out of memory");
  }
}

/* n random spheres and the floor, prepared, indexed. */
static void random_scene(Scene *s, Rng *g, int n)
{
  spheres_on_floor(s, g, n, 10);
  cr_assert(scene_prepare(s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  cr_assert(accel_build(s), "accel_build (given code) failed");
}

static vec3s random_unit(Rng *g)
{
  return glms_vec3_normalize(vec_make(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1)));
}

static Ray random_ray(const Scene *s, Rng *g)
{
  Ray r = {.o = vec_make(uni(g, -12, 12), uni(g, 0.5f, 8), uni(g, -12, 12))};
  if (rng_float(g) < 0.3f) { /* aim at the rim of a sphere: grazing */
    const Sphere *sp = &s->instances[1 + (int)(rng_float(g) * (float)(s->n_instances - 1))].sphere;
    vec3s side = random_unit(g);
    vec3s aim = glms_vec3_add(sp->center, glms_vec3_scale(side, sp->radius));
    r.d = glms_vec3_normalize(glms_vec3_sub(aim, r.o));
  } else {
    r.d = random_unit(g);
  }
  return r;
}

/* ------------------------------------------------------------ blame */

/* The index (given code) tests only the instances a ray can meet, and takes
 * sphere_hit_t's and plane_hit_t's answers as they come: where it and the
 * plain loop disagree, either a shape function answered this ray wrongly
 * (the student's, step 02) or the index is wrong (the course's). The exact
 * answer of one instance in long double (the differences and products of
 * floats are exact there): its nearest root in (0, inf), and whether the
 * float answer can be asked for (hit or miss clear by more than 2 float
 * roundings of the distance, as stress test 2 asks; a root not within 4
 * roundings of 0). */
typedef struct Exact {
  long double t;
  bool decidable;
} Exact;

static Exact exact_sphere(const Sphere *sp, Ray r)
{
  long double f[3], d[3], b = 0, dd = 0, ff = 0, rr = (long double)sp->radius * sp->radius;
  for (int k = 0; k < 3; k++) {
    f[k] = (long double)r.o.raw[k] - sp->center.raw[k];
    d[k] = r.d.raw[k];
    b += f[k] * d[k], dd += d[k] * d[k], ff += f[k] * f[k];
  }
  long double h = sqrtl(fmaxl(ff - b * b / dd, 0.0L)), dist = sqrtl(ff);
  long double disc = b * b - dd * (ff - rr), t = INFINITY;
  if (disc >= 0) {
    long double sq = sqrtl(disc), t0 = (-b - sq) / dd, t1 = (-b + sq) / dd;
    t = t0 > 0 ? t0 : t1 > 0 ? t1 : INFINITY;
  }
  long double eps = 0x1p-24L * (dist + sp->radius);
  bool near0 = disc >= 0 && (fabsl((-b - sqrtl(disc)) / dd) <= 4 * eps ||
                             fabsl((-b + sqrtl(disc)) / dd) <= 4 * eps);
  return (Exact){t, fabsl(h - sp->radius) > 2 * 0x1p-24L * dist && !near0};
}

static Exact exact_plane(const Plane *pl, Ray r)
{
  long double num = 0, den = 0, scale = 0;
  for (int k = 0; k < 3; k++) {
    long double q = pl->point.raw[k], o = r.o.raw[k];
    num += (q - o) * pl->normal.raw[k], den += (long double)r.d.raw[k] * pl->normal.raw[k];
    scale += fabsl(q) + fabsl(o);
  }
  long double t = num / den;
  bool hit = t > 0 && isfinite(t);
  return (Exact){hit ? t : INFINITY, fabsl(num) > 4 * 0x1p-24L * scale && fabsl(den) > 1e-6L};
}

/* Within 4 float roundings of each other (x, y > 0). */
static bool close_ld(long double x, long double y)
{
  return fabsl(x - y) <= 4 * 0x1p-24L * fmaxl(fabsl(x), fabsl(y));
}

/* The first instance whose shape function answered r wrongly (-1: none):
 * hit or miss against a decidable exact answer, t off by more than 1e-4
 * relative (test_scene.c's tolerance), or NaN; its answer and the exact one
 * in *got, *want. Else *close tells whether the ray is one that no float
 * answer decides: a hit within 2 roundings of the silhouette, an exact
 * distance within 4 roundings of tmax or of the loop's `best` by another
 * instance. */
static int wrong_instance(const Scene *s, Ray r, float tmax, float best, float *got, double *want,
                          bool *close)
{
  *close = false;
  for (int m = 0; m < s->n_instances; m++) {
    const Instance *in = &s->instances[m];
    if (in->shape != SHAPE_SPHERE && in->shape != SHAPE_PLANE)
      continue;
    Exact e = in->shape == SHAPE_SPHERE ? exact_sphere(&in->sphere, r) : exact_plane(&in->plane, r);
    float t = scene_instance_hit_t(in, r, INFINITY);
    bool wrong = isnan(t) || (e.decidable && (t < INFINITY) != (e.t < INFINITY)) ||
                 (e.decidable && t < INFINITY && fabsl(t - e.t) > 1e-4L * e.t);
    if (wrong) {
      *got = t, *want = (double)e.t;
      return m;
    }
    *close = *close || (!e.decidable && t < tmax) ||
             (e.t < INFINITY && ((isfinite(tmax) && close_ld(e.t, tmax)) ||
                                 (best < tmax && t != best && close_ld(e.t, best))));
  }
  return -1;
}

/* The checks of a test of the index: the index itself (given code), and the
 * shape functions it calls (the student's, step 02). */
typedef struct Blame {
  Check index, sphere, plane;
} Blame;

static Blame blame_make(const char *index_fn, const char *index_doc)
{
  return (Blame){CHECK(index_fn, index_doc),
                 CHECK("sphere_hit_t (step 02)", "docs/02-intersection.md, \"What you write\""),
                 CHECK("plane_hit_t (step 02)", "docs/02-intersection.md, \"What you write\"")};
}

static void blame_done(Blame *b)
{
  CHECK_DONE(&b->sphere);
  CHECK_DONE(&b->plane);
  CHECK_DONE(&b->index);
}

/* One answer of the index on ray r (tmax, and the loop's closest t `best`
 * or tmax), `ok` when it is the plain loop's. Where they disagree, the
 * message names the shape function that answered r wrongly; else, on a ray
 * no float answer decides, either answer passes; else it names the index.
 * `what` says the case and both answers. */
static void blame(Blame *b, const Scene *s, Ray r, float tmax, float best, bool ok,
                  const char *what)
{
  float got;
  double want;
  bool close = false;
  int m = ok ? -1 : wrong_instance(s, r, tmax, best, &got, &want, &close);
  if (m < 0) {
    ok = ok || close;
    CHECK_THAT(&b->index, ok, "%s", what);
    return;
  }
  const Instance *in = &s->instances[m];
  char shape[200];
  if (in->shape == SHAPE_SPHERE)
    snprintf(shape, sizeof shape, "instance #%d, the sphere of radius %.9g at (%.9g, %.9g, %.9g)",
             m, in->sphere.radius, in->sphere.center.x, in->sphere.center.y, in->sphere.center.z);
  else
    snprintf(shape, sizeof shape, "instance #%d, the plane through (%.9g, %.9g, %.9g) with "
             "normal (%.9g, %.9g, %.9g)", m, in->plane.point.x, in->plane.point.y,
             in->plane.point.z, in->plane.normal.x, in->plane.normal.y, in->plane.normal.z);
  CHECK_THAT(in->shape == SHAPE_SPHERE ? &b->sphere : &b->plane, false, "%s\n  the ray o = "
             "(%.9g, %.9g, %.9g), d = (%.9g, %.9g, %.9g) gets a wrong answer from %s, so the "
             "scene index (given code), which tests only the shapes a ray can meet, and the "
             "plain loop disagree: `make stress` tests 1 and 2 ask for the refinements that "
             "answer such rays right\n  expected t = %.9g (long double)\n  got      t = %.9g",
             what, r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, shape, want, (double)got);
}

/* The index's answers for `rays` random rays against the loop's, on the
 * prepared and indexed scene s (`what` names it in the messages). */
static void check_answers(const Scene *ps, Rng *gen, const char *what, int rays)
{
  Scene s = *ps;
  Rng g = *gen;
  int n = s.n_instances;
  cr_assert(s.index, "accel_build (given code) built no index");
  Blame c = blame_make("scene index (given code: fast/index/)", "docs/performance.md, \"The scene queries\"");
  for (int k = 0; k < rays; k++) {
    Ray r = random_ray(&s, &g);
    if (k % 4 == 3) /* from the eye: the rays the cones know */
      r.o = s.camera.eye;
    float tmax = k % 3 ? INFINITY : uni(&g, 0.1f, 20);
    float best = tmax, got = tmax;
    int want = -1;
    for (int m = 0; m < s.n_instances; m++) {
      float t = scene_instance_hit_t(&s.instances[m], r, best);
      if (t < best) {
        best = t;
        want = m;
      }
    }
    const Instance *hit = s.index->closest(&s, &r, &got);
    int got_m = hit ? (int)(hit - s.instances) : -1;
    bool any = s.index->any(&s, &r, tmax);
    char msg[CHECK_TEXT];
    snprintf(msg, sizeof msg, "%s, %d instances, ray %d: the closest instance (-1: none), its "
             "t and whether some hit lies before tmax differ from the loop over "
             "scene_instance_hit_t\n  expected #%d, t = %.9g, %s\n  got      #%d, t = %.9g, %s",
             what, n, k, want, (double)best, want >= 0 ? "a hit" : "none", got_m, (double)got,
             any ? "a hit" : "none");
    blame(&c, &s, r, tmax, best,
          want == got_m && (want < 0 || best == got) && any == (want >= 0), msg);
  }
  blame_done(&c);
  *gen = g;
}

static void check_layout(const char *layout, int n, int rays)
{
  setenv("RT_ACCEL", layout, 1);
  Rng g = rng_make(7, (uint32_t)n, 0);
  Scene s;
  random_scene(&s, &g, n);
  check_answers(&s, &g, layout, rays);
  accel_free(&s);
  scene_free(&s);
  unsetenv("RT_ACCEL");
}

Test(accel, flat_layout_gives_the_plain_loops_answers)
{
  stress_step(2);
  for (int n = 1; n <= 40; n += 13)
    check_layout("flat", n, 20000);
}

Test(accel, hierarchy_gives_the_plain_loops_answers)
{
  stress_step(2);
  for (int n = 1; n <= 3000; n = 3 * n + 7)
    check_layout("bvh", n, 20000);
}

/* Above 16384 spheres the hierarchy is built over Morton-ordered clusters
 * (fast/index/bvh.c), its sort split among the threads: the same answers
 * with one thread and with three. */
Test(accel, clustered_hierarchy_gives_the_plain_loops_answers)
{
  stress_step(2);
  for (int threads = 1; threads <= 3; threads += 2) {
    omp_set_num_threads(threads);
    check_layout("bvh", 40000, 1500);
  }
}

/* Scenes of more than 65536 instances are sorted in blocks, and when their
 * lit spheres are consecutive instances the index keeps no list of them
 * (fast/index/accel.c, sort_instances): the same answers with the spheres
 * before the floor, with the floor in their middle, and for a few spheres
 * after 70 000 planes (the cones' layout). */
Test(accel, large_scenes_give_the_plain_loops_answers)
{
  stress_step(2);
  omp_set_num_threads(2);
  for (int variant = 0; variant < 3; variant++) {
    Rng g = rng_make(13, (uint32_t)variant, 0);
    Scene s;
    if (variant < 2) {
      spheres_on_floor(&s, &g, 70000, 300);
    } else {
      scene_init(&s);
      Material m = {.name = "m", .diffuse = vec_make(0.5f, 0.5f, 0.5f)};
      cr_assert(scene_add_material(&s, &m), "out of memory");
      for (int k = 0; k < 70000; k++) {
        Plane below = plane_make(vec_make(0, -100.0f - (float)k, 0), vec_make(0, 1, 0));
        Instance pl = {.shape = SHAPE_PLANE, .light = -1, .plane = below};
        cr_assert(scene_add_instance(&s, &pl), "out of memory");
      }
      for (int k = 0; k < 10; k++) {
        Instance in = {.shape = SHAPE_SPHERE, .light = -1,
                       .sphere = {vec_make(uni(&g, -5, 5), uni(&g, 0, 3), uni(&g, -5, 5)), 1}};
        cr_assert(scene_add_instance(&s, &in), "out of memory");
      }
    }
    if (variant < 2) { /* the floor after the spheres, or in their middle */
      int to = variant == 0 ? 70000 : 35000;
      Instance floor = s.instances[0];
      s.instances[0] = s.instances[to];
      s.instances[to] = floor;
    }
    cr_assert(scene_prepare(&s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
    cr_assert(accel_build(&s), "accel_build (given code) failed");
    static const char *what[] = {"spheres before the floor", "floor among the spheres",
                                 "10 spheres after 70000 planes"};
    check_answers(&s, &g, what[variant], 2000);
    accel_free(&s);
    scene_free(&s);
  }
}

/* An array of balls as bvh_build reads it. */
static Balls packed(const Ball *balls)
{
  return (Balls){(const char *)balls, sizeof *balls};
}

/* The closest-hit traversal takes an inner node's children nearer first by
 * the node's axis (bvh.h): nodes[index] must be the lower child along it.
 * With balls of one size, a child's box is its centres' bounds widened
 * alike (but for the margin's 2^-20 of the coordinates), so its middle is
 * about theirs. Over random balls, and balls on a plane
 * (one axis flat), for the heuristic's build (3 000 balls) and the
 * clustered one (40 000). */
Test(accel, children_lie_in_order_along_their_axis)
{
  stress_step(2);
  Check c = CHECK("bvh_build (given code: fast/index/bvh.c)",
                  "docs/performance.md, \"The scene queries\"");
  for (int n = 3000; n <= 40000; n += 37000) {
    for (int flat = 0; flat < 2; flat++) {
      Rng g = rng_make(11, (uint32_t)n, (uint32_t)flat);
      Ball *balls = malloc((size_t)n * sizeof *balls);
      cr_assert(balls, "out of memory");
      for (int k = 0; k < n; k++)
        balls[k] = (Ball){uni(&g, -10, 10), flat ? 0.5f : uni(&g, -3, 3), uni(&g, -10, 10), 0.01f};
      Bvh bvh;
      cr_assert(bvh_build(&bvh, packed(balls), n, 4), "bvh_build: out of memory");
      int inner = 0;
      for (int k = 0; k < bvh.n_nodes; k++) {
        const BvhNode *nd = &bvh.nodes[k];
        if (nd->meta >= 0) /* a leaf (inner nodes: -1 - axis) */
          continue;
        int a = -1 - nd->meta;
        const BvhNode *lo = &bvh.nodes[nd->index], *hi = &bvh.nodes[nd->index + 1];
        inner++;
        CHECK_THAT(&c, lo->lo[a] + lo->hi[a] <= hi->lo[a] + hi->hi[a],
                   "%d balls%s, node %d, axis %d: the first child's middle (%.9g) is at most "
                   "the second's (%.9g)", n, flat ? " on a plane" : "", k, a,
                   0.5 * (lo->lo[a] + lo->hi[a]), 0.5 * (hi->lo[a] + hi->hi[a]));
      }
      CHECK_REQUIRE(&c, inner > 0, "%d balls: the tree has inner nodes", n);
      bvh_free(&bvh);
      free(balls);
    }
  }
  CHECK_DONE(&c);
}

/* Walk the subtree at `node`: each slot entered once (seen), each node's box
 * holding its children's or its balls' cubes, each ball in one leaf
 * (covered). Returns the nodes entered. */
static int walk(Check *c, const Bvh *bvh, const Ball *balls, int node, int depth,
                unsigned char *seen, unsigned char *covered)
{
  CHECK_REQUIRE(c, node >= 0 && node < bvh->n_nodes && depth < 100,
                "node %d (depth %d): expected a slot below %d", node, depth, bvh->n_nodes);
  CHECK_REQUIRE(c, !seen[node], "node %d is the child of two nodes", node);
  seen[node] = 1;
  const BvhNode *nd = &bvh->nodes[node];
  if (nd->meta > 0) {
    CHECK_REQUIRE(c, nd->index >= 0 && nd->index + nd->meta <= bvh->n_items,
                  "leaf %d: items %d .. %d, expected within 0 .. %d", node, nd->index,
                  nd->index + nd->meta, bvh->n_items);
    for (int k = nd->index; k < nd->index + nd->meta; k++) {
      int id = bvh->order[k];
      CHECK_REQUIRE(c, id >= 0 && id < bvh->n_items && !covered[id],
                    "leaf %d: ball %d is in two leaves (or out of range)", node, id);
      covered[id] = 1;
      Box4 box = ball_box(balls[id]);
      for (int a = 0; a < 3; a++)
        CHECK_REQUIRE(c, nd->lo[a] <= box.lo[a] && box.hi[a] <= nd->hi[a],
                      "leaf %d, axis %d: [%.9g, %.9g] does not hold ball %d's cube "
                      "[%.9g, %.9g]", node, a, nd->lo[a], nd->hi[a], id, box.lo[a], box.hi[a]);
    }
    return 1;
  }
  int entered = 1;
  for (int s = 0; s < 2; s++) {
    const BvhNode *ch = &bvh->nodes[nd->index + s];
    for (int a = 0; a < 3; a++)
      CHECK_REQUIRE(c, nd->lo[a] <= ch->lo[a] && ch->hi[a] <= nd->hi[a],
                    "node %d, axis %d: [%.9g, %.9g] does not hold child %d's [%.9g, %.9g]",
                    node, a, nd->lo[a], nd->hi[a], nd->index + s, ch->lo[a], ch->hi[a]);
    entered += walk(c, bvh, balls, nd->index + s, depth + 1, seen, covered);
  }
  return entered;
}

/* The tree's shape, whatever its layout in the array: every slot one node
 * of the tree, entered from the root once, and every ball in one leaf under
 * boxes that hold it; for one build over all the balls and for the
 * clustered build (more than 16384), with leaves of 1 to 4. And the same
 * tree, byte for byte, built with 1 and with 3 threads. */
Test(accel, every_slot_is_one_node_and_every_ball_in_one_leaf)
{
  stress_step(2);
  Check c = CHECK("bvh_build (given code: fast/index/bvh.c)",
                  "docs/performance.md, \"The scene queries\"");
  static const int sizes[] = {1000, 40000};
  for (int s = 0; s < 2; s++)
    for (int leaf = 1; leaf <= 4; leaf += 3) {
      int n = sizes[s];
      Rng g = rng_make(12, (uint32_t)n, (uint32_t)leaf);
      Ball *balls = malloc((size_t)n * sizeof *balls);
      unsigned char *covered = calloc((size_t)n, 1), *seen = calloc(2 * (size_t)n, 1);
      cr_assert(balls && covered && seen, "out of memory");
      for (int k = 0; k < n; k++) /* clumps, some balls on one spot */
        balls[k] = k % 13 == 3 ? balls[k - 1]
                               : (Ball){uni(&g, -10, 10) * (k % 3 ? 1.0f : 0.01f),
                                        uni(&g, 0, 2), uni(&g, -10, 10), uni(&g, 1e-3f, 0.3f)};
      Bvh bvh;
      int first_threads = omp_get_max_threads();
      cr_assert(bvh_build(&bvh, packed(balls), n, leaf), "bvh_build: out of memory");
      int entered = walk(&c, &bvh, balls, 0, 0, seen, covered);
      CHECK_INT(&c, bvh.n_nodes, entered, "%d balls, leaves of at most %d: nodes entered from "
                "the root, against n_nodes", n, leaf);
      int missing = 0;
      for (int k = 0; k < n; k++)
        missing += !covered[k];
      CHECK_INT(&c, 0, missing, "%d balls, leaves of at most %d: balls in no leaf", n, leaf);
      for (int threads = 1; threads <= 3; threads += 2) { /* bvh.h: any thread count */
        omp_set_num_threads(threads);
        Bvh again;
        cr_assert(bvh_build(&again, packed(balls), n, leaf), "bvh_build: out of memory");
        bool same = again.n_nodes == bvh.n_nodes &&
                    !memcmp(again.nodes, bvh.nodes, (size_t)bvh.n_nodes * sizeof *bvh.nodes) &&
                    !memcmp(again.order, bvh.order, (size_t)n * sizeof *bvh.order);
        CHECK_THAT(&c, same, "%d balls, leaves of at most %d: the tree built with %d thread%s "
                   "differs from the one built with %d", n, leaf, threads, threads > 1 ? "s" : "",
                   first_threads);
        bvh_free(&again);
      }
      omp_set_num_threads(2);
      bvh_free(&bvh);
      free(balls);
      free(covered);
      free(seen);
    }
  CHECK_DONE(&c);
}

/* ------------------------------------------------------------------ cones */

/* The plain loop's answers: the closest instance (first of equal distances)
 * and whether some lit shape lies on the ray before tmax. */
static int loop_closest(const Scene *s, Ray r, float *t)
{
  int want = -1;
  for (int m = 0; m < s->n_instances; m++) {
    float tm = scene_instance_hit_t(&s->instances[m], r, *t);
    if (tm < *t) {
      *t = tm;
      want = m;
    }
  }
  return want;
}

static bool loop_any(const Scene *s, Ray r, float tmax)
{
  for (int m = 0; m < s->n_shapes; m++)
    if (scene_instance_hit_t(&s->instances[m], r, tmax) < tmax)
      return true;
  return false;
}

/* n spheres (1..16: the scenes that get cones), the floor, in odd variants a
 * tilted plane too; an eye, two point lights and a directional one. Variant
 * 2 puts the eye inside a sphere, variant 3 a light inside one and the other
 * on a sphere's surface. */
static void cone_scene(Scene *s, Rng *g, int n, int variant)
{
  spheres_on_floor(s, g, n, 6);
  if (variant % 2) {
    Plane tilted = plane_make(vec_make(0, -0.5f, 0), vec_make(0.1f, 1, 0.05f));
    Instance pl = {.shape = SHAPE_PLANE, .light = -1, .plane = tilted};
    cr_assert(scene_add_instance(s, &pl), "out of memory");
  }
  const Sphere *inside = &s->instances[1 + (int)(rng_float(g) * (float)n)].sphere;
  s->camera.eye = variant == 2 ? inside->center : vec_make(uni(g, -12, 12), uni(g, 0.5f, 8), 12);
  s->camera.center = vec_make(uni(g, -1, 1), uni(g, 0, 1), uni(g, -1, 1));
  for (int k = 0; k < 2; k++) {
    Light l = {.type = LIGHT_POINT, .power = vec_make(10, 10, 10),
               .position = vec_make(uni(g, -8, 8), uni(g, 3, 9), uni(g, -8, 8))};
    if (variant == 3)
      l.position = k == 0 ? inside->center
                          : glms_vec3_add(inside->center, vec_make(0, inside->radius, 0));
    cr_assert(scene_add_light(s, &l), "out of memory");
  }
  Light sun = {.type = LIGHT_DIRECTIONAL, .irradiance = vec_make(1, 1, 1),
               .direction = glms_vec3_normalize(vec_make(uni(g, -1, 1), -1, uni(g, -1, 1)))};
  cr_assert(scene_add_light(s, &sun), "out of memory");
  cr_assert(scene_prepare(s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  cr_assert(accel_build(s), "accel_build (given code) failed");
}

/* A direction from `from` toward a random point of sphere k's rim as seen
 * from there (grazing), or a random direction. */
static vec3s aim(const Scene *s, Rng *g, vec3s from, int n)
{
  if (rng_float(g) < 0.5f)
    return random_unit(g);
  const Sphere *sp = &s->instances[1 + (int)(rng_float(g) * (float)n)].sphere;
  vec3s to_c = glms_vec3_sub(sp->center, from), side = random_unit(g);
  float cc = glms_vec3_dot(to_c, to_c);
  if (!(cc > 0.0f)) /* from the centre (the eye inside a sphere): any way */
    return side;
  side = glms_vec3_normalize(
      glms_vec3_sub(side, glms_vec3_scale(to_c, glms_vec3_dot(side, to_c) / cc)));
  vec3s rim = glms_vec3_add(sp->center, glms_vec3_scale(side, sp->radius * uni(g, 0.999f, 1.001f)));
  return glms_vec3_normalize(glms_vec3_sub(rim, from));
}

/* An origin: around the spheres, on the floor, under it, or `far` times
 * farther out. */
static vec3s origin(Rng *g, float far)
{
  float pick = rng_float(g);
  vec3s o = vec_make(uni(g, -10, 10), uni(g, 0, 6), uni(g, -10, 10));
  if (pick < 0.2f)
    o.y = 0.0f;
  else if (pick < 0.3f)
    o.y = -uni(g, 0, 2);
  else if (pick < 0.4f)
    o = glms_vec3_scale(o, far);
  return o;
}

static void check_ray(Blame *c, const Scene *s, Ray r, float tmax, bool closest, const char *what,
                      int n, int variant, int k)
{
  char msg[CHECK_TEXT];
  if (closest) {
    float t_want = tmax, t_got = tmax;
    int want = loop_closest(s, r, &t_want);
    const Instance *hit = s->index->closest(s, &r, &t_got);
    int got = hit ? (int)(hit - s->instances) : -1;
    snprintf(msg, sizeof msg, "%d spheres, variant %d, %s %d: the closest instance (-1: "
             "none) and its t differ from the loop over scene_instance_hit_t\n  expected "
             "#%d, t = %.9g\n  got      #%d, t = %.9g", n, variant, what, k, want,
             (double)t_want, got, (double)t_got);
    blame(c, s, r, tmax, t_want, want == got && (want < 0 || t_want == t_got), msg);
  }
  bool want_any = loop_any(s, r, tmax), got_any = s->index->any(s, &r, tmax);
  snprintf(msg, sizeof msg, "%d spheres, variant %d, %s %d: whether some lit shape lies "
           "before tmax = %.9g differs from the plain loop\n  expected %s\n  got      %s", n,
           variant, what, k, (double)tmax, want_any ? "yes" : "no", got_any ? "yes" : "no");
  blame(c, s, r, tmax, tmax, want_any == got_any, msg);
}

/* Up to 16 spheres the index chooses each camera ray's and shadow ray's
 * spheres from their cones seen from the eye and the point lights, and
 * their discs across the directional lights (fast/index/cones.c): the
 * plain loop's answers for camera rays, the shadow rays spawned from their
 * hits, rays whose end strays from a light by 1e-8 to 1e-2 of its distance
 * (inside and outside the cones' margin), rays along the directional light
 * from anywhere, grazing rims, and an eye or a light inside a sphere. */
Test(accel, cones_give_the_plain_loops_answers)
{
  stress_step(5);
  Blame c = blame_make("scene index (given code: fast/index/cones.c)",
                       "docs/performance.md, \"Cones from the eye and the lights\"");
  const int sizes[] = {1, 2, 5, 8, 9, 16};
  for (int variant = 0; variant < 4; variant++)
    for (int si = 0; si < 6; si++) {
      int n = sizes[si];
      for (int rep = 0; rep < 4; rep++) {
        Rng g = rng_make(11, (uint32_t)(variant * 100 + n * 10 + rep), 0);
        Scene s;
        cone_scene(&s, &g, n, variant);
        for (int k = 0; k < 2000; k++) {
          Ray cam = {.o = s.camera.eye, .d = aim(&s, &g, s.camera.eye, n)};
          check_ray(&c, &s, cam, INFINITY, true, "camera ray", n, variant, k);
          Hit hit;
          if (scene_intersect(&s, cam, INFINITY, &hit)) {
            for (int li = 0; li < s.n_lights; li++) {
              vec3s l;
              float dist;
              light_incident(&s.lights[li], hit.p, hit.p_err, &l, &dist);
              if (dist > 0.0f)
                check_ray(&c, &s, ray_spawn(&hit, l), ray_shadow_tmax(dist), false,
                          "shadow ray from a camera ray's hit", n, variant, k);
            }
          }
          /* Ends that stray up to 1e-2 of the distance from the light: some
           * beyond the cones' margin, left to the box. Origins farther out
           * (up to 1e2) only with ends the cones take (a stray of at most
           * 1e-6): from 1e3 and more, a tiny sphere's hit within a float step
           * of tmax is a hit for sphere_hit_t and beyond tmax for the box
           * (docs/performance.md, "Cones from the eye and the lights"). */
          const Light *pt = &s.lights[k % 2];
          float rel = powf(10.0f, -uni(&g, 2, 8));
          vec3s o = origin(&g, rel <= 1e-6f ? 10.0f : 1.0f);
          float stray = rel * glms_vec3_distance(o, pt->position);
          vec3s end = glms_vec3_add(pt->position, glms_vec3_scale(random_unit(&g), stray));
          if (rng_float(&g) < 0.5f) /* through a sphere's rim on its way to the light */
            o = glms_vec3_add(end, glms_vec3_scale(aim(&s, &g, end, n), -uni(&g, 1, 30)));
          vec3s to_end = glms_vec3_sub(end, o);
          Ray r = {.o = o, .d = glms_vec3_normalize(to_end)};
          check_ray(&c, &s, r, glms_vec3_norm(to_end), false, "ray ending near a point light", n,
                    variant, k);
          Ray along = {.o = origin(&g, k % 2 ? 10.0f : 1e6f), .d = glms_vec3_negate(s.lights[2].direction)};
          if (k % 3 == 1) { /* past a sphere's rim, within 1e-3 of its radius */
            const Sphere *sp = &s.instances[1 + k % n].sphere;
            vec3s side = random_unit(&g);
            side = glms_vec3_normalize(
                glms_vec3_sub(side, glms_vec3_scale(along.d, glms_vec3_dot(side, along.d))));
            vec3s rim = glms_vec3_add(sp->center,
                                      glms_vec3_scale(side, sp->radius * uni(&g, 0.999f, 1.001f)));
            along.o = glms_vec3_sub(rim, glms_vec3_scale(along.d, uni(&g, 0.5f, 50)));
          }
          check_ray(&c, &s, along, k % 3 ? INFINITY : uni(&g, 0.1f, 20), false,
                    "ray along the directional light", n, variant, k);
        }
        accel_free(&s);
        scene_free(&s);
      }
    }
  blame_done(&c);
}

/* Spheres and (in odd variants) tilted discs over the floor under an area
 * light, 16 light samples: the any-hit query recognises the shadow rays
 * toward the light by their end and tests only the shapes that may stand
 * between their origin and the light (fast/index/accel.c, hull.c). */
static void area_scene(Scene *s, Rng *g, int n, int variant)
{
  spheres_on_floor(s, g, n, 4);
  for (int k = 0; variant % 2 && k < 3; k++) {
    Instance d = {.shape = SHAPE_DISC, .light = -1,
                  .disc = disc_make(vec_make(uni(g, -3, 3), uni(g, 0.5f, 2.5f), uni(g, -3, 3)),
                                    random_unit(g), uni(g, 0.2f, 1.0f))};
    cr_assert(scene_add_instance(s, &d), "out of memory");
  }
  Light area = {.type = LIGHT_AREA, .power = vec_make(10, 10, 10),
                .quad = quad_make(vec_make(uni(g, -2, 0), uni(g, 4, 6), uni(g, -2, 0)),
                                  vec_make(uni(g, 0.5f, 3), 0, uni(g, -0.5f, 0.5f)),
                                  vec_make(uni(g, -0.5f, 0.5f), uni(g, -1, 0), uni(g, 0.5f, 3)))};
  cr_assert(scene_add_light(s, &area), "out of memory");
  s->light_samples = 16;
  cr_assert(scene_prepare(s, SCENE_CAMERA | SCENE_LIGHTS | SCENE_AREA_LIGHTS), "out of memory");
  cr_assert(accel_build(s), "accel_build (given code) failed");
}

/* The shadow rays of shading points toward an area light (the step's own:
 * ray_spawn toward a random point of the light, ray_shadow_tmax of its
 * distance), from points on the floor, the spheres and the discs: the plain
 * loop's answers, whether the index tests the shapes the hull leaves (none,
 * a few) or the whole scene; each of the first two must occur often. */
Test(accel, area_light_shadow_rays_give_the_plain_loops_answers)
{
  stress_step(8);
  Blame c = blame_make("scene index (given code: fast/index/accel.c, hull.c)",
                       "docs/performance.md, \"Shadow rays toward an area light\"");
  static const char *const layouts[] = {"flat", "bvh", ""};
  int kinds[3] = {0, 0, 0}; /* points whose rays test no shape, a few, the whole index */
  for (int variant = 0; variant < 6; variant++) {
    setenv("RT_ACCEL", layouts[variant % 3], 1);
    for (int rep = 0; rep < 8; rep++) {
      int n = 1 + rep * 5 + variant;
      Rng g = rng_make(17, (uint32_t)(variant * 100 + rep), 0);
      Scene s;
      area_scene(&s, &g, n, variant);
      const Quad *q = &s.lights[0].quad;
      for (int p = 0; p < 300; p++) {
        Ray cam = {.o = vec_make(uni(&g, -5, 5), 7, uni(&g, -5, 5)),
                   .d = glms_vec3_normalize(vec_make(uni(&g, -0.6f, 0.6f), -1, uni(&g, -0.6f, 0.6f)))};
        Hit hit;
        if (!scene_intersect(&s, cam, INFINITY, &hit) || hit.light >= 0)
          continue;
        int ids[8];
        int shapes = accel_area_shapes(&s, ray_spawn(&hit, hit.n).o, q, ids, 8);
        kinds[shapes == 0 ? 0 : shapes > 0 ? 1 : 2]++;
        for (int k = 0; k < 32; k++) {
          float a = rng_float(&g), b = rng_float(&g);
          vec3s x = quad_point(q, a, b), to_x = glms_vec3_sub(x, hit.p);
          float dist = glms_vec3_norm(to_x);
          vec3s l = glms_vec3_scale(to_x, 1.0f / dist);
          if (!(glms_vec3_dot(hit.n, l) > 0.0f))
            continue;
          check_ray(&c, &s, ray_spawn(&hit, l), ray_shadow_tmax(dist), false,
                    "shadow ray toward the area light", n, variant, k);
        }
      }
      accel_free(&s);
      scene_free(&s);
    }
  }
  unsetenv("RT_ACCEL");
  blame_done(&c);
  Check k = CHECK("accel_area_shapes (given code: fast/index/accel.c)",
                  "docs/performance.md, \"Shadow rays toward an area light\"");
  CHECK_THAT(&k, kinds[0] > 500 && kinds[1] > 500, "shading points whose shadow rays test no "
             "shape %d, a few %d, the whole index %d: expected more than 500 of the first two "
             "(the test must matter)", kinds[0], kinds[1], kinds[2]);
}
