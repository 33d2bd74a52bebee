/* Step 05's shadow test against the lecture's method: in random scenes, for
 * every point the camera sees and every light in front of it, the lecture's
 * closest-hit shadow ray traced in long double here decides lit or blocked,
 * and shade_incident (through shade_visible) must agree. Any correct solution
 * passes, the lecture's own version included. docs/05-shadows.md, "What you
 * write". */
#include "check.h"
#include "rng.h"
#include "shadow.h"
#include "shadow_scene.h"

/* Long double roots of the line o + t d (d unit) with instance `in`; their
 * number. *tangent: the line's distance to the sphere's silhouette. */
static int line_roots(const Instance *in, const long double o[3], const long double d[3],
                      long double t[2], long double *tangent)
{
  *tangent = INFINITY;
  if (in->shape == SHAPE_PLANE) {
    long double dn = 0.0L, qn = 0.0L;
    for (int a = 0; a < 3; a++) {
      dn += d[a] * in->plane.normal.raw[a];
      qn += ((long double)in->plane.point.raw[a] - o[a]) * in->plane.normal.raw[a];
    }
    if (dn == 0.0L)
      return 0;
    t[0] = qn / dn;
    return 1;
  }
  long double f[3], b = 0.0L, ff = 0.0L, r = in->sphere.radius;
  for (int a = 0; a < 3; a++) {
    f[a] = o[a] - in->sphere.center.raw[a];
    b += f[a] * d[a];
    ff += f[a] * f[a];
  }
  long double dist_line = sqrtl(fmaxl(0.0L, ff - b * b));
  *tangent = fabsl(dist_line - r);
  if (dist_line >= r)
    return 0;
  long double half = sqrtl(r * r - dist_line * dist_line);
  t[0] = -b - half;
  t[1] = -b + half;
  return 2;
}

/* The lecture's method, in long double: trace the ray from the hit point p
 * toward the light and take its closest hit; the light is visible when that
 * hit is not closer than the light (the lecture's lights have a shape, "the
 * first hit is the light"; here they have none). The root at p itself, on the
 * surface p lies on, is what the lecture's offset skips. *unclear when a
 * surface, a silhouette or the light lies within 1e-4 of where the answer
 * would change (far above float rounding at this scene's size). */
static bool lecture_visible(const Scene *s, const Hit *h, vec3s l, float dist, bool *unclear)
{
  const long double margin = 1e-4L;
  long double o[3], d[3], n = sqrtl((long double)l.x * l.x + (long double)l.y * l.y +
                                    (long double)l.z * l.z);
  for (int a = 0; a < 3; a++) {
    o[a] = h->p.raw[a];
    d[a] = l.raw[a] / n;
  }
  bool visible = true;
  *unclear = false;
  for (int k = 0; k < s->n_instances; k++) {
    const Instance *in = &s->instances[k];
    long double t[2], tangent;
    int roots = line_roots(in, o, d, t, &tangent);
    *unclear |= tangent < margin;
    for (int q = 0; q < roots; q++) {
      if (in == h->inst && fabsl(t[q]) < margin)
        continue; /* p's own surface */
      *unclear |= fabsl(t[q]) < margin || fabsl(t[q] - dist) < margin;
      visible &= !(t[q] > 0.0L && t[q] < dist);
    }
  }
  return visible;
}

/* A random point of the box lo + [0, size) per axis, drawn x, y, z in turn. */
static vec3s box_point(Rng *rng, vec3s lo, vec3s size)
{
  float x = lo.x + size.x * rng_float(rng), y = lo.y + size.y * rng_float(rng),
        z = lo.z + size.z * rng_float(rng);
  return vec_make(x, y, z);
}

/* Random spheres over a floor, a point and a directional light. */
static void random_scene(Scene *s, Rng *rng)
{
  scene_start(s);
  add_plane(s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  for (int k = 0; k < 8; k++) {
    float r = 0.2f + 0.8f * rng_float(rng);
    add_sphere(s, box_point(rng, vec_make(-3.0f, 0.0f, -3.0f), vec_make(6.0f, 2.5f, 6.0f)), r);
  }
  add_point(s, box_point(rng, vec_make(-4.0f, 1.0f, -4.0f), vec_make(8.0f, 5.0f, 8.0f)),
            vec_make(10.0f, 10.0f, 10.0f));
  add_directional(s, box_point(rng, vec_make(-0.5f, -1.0f, -0.5f), vec_make(1.0f, 0.0f, 1.0f)),
                  vec_make(1.0f, 1.0f, 1.0f));
  prepare(s);
}

Test(shadows, agrees_with_the_lectures_closest_hit_method)
{
  int compared = 0, lit = 0, unclear_count = 0;
  Check c = shadow_check();
  for (uint32_t config = 0; config < 40; config++) {
    Rng rng = rng_make(11, config, 0);
    Scene s;
    random_scene(&s, &rng);
    for (int k = 0; k < 500; k++) {
      vec3s eye = vec_make(0.0f, 4.0f, 10.0f);
      vec3s target = box_point(&rng, vec_make(-4.0f, 0.0f, -4.0f), vec_make(8.0f, 2.0f, 8.0f));
      Ray r = {.o = eye, .d = glms_vec3_normalize(glms_vec3_sub(target, eye))};
      Hit h;
      if (!scene_intersect(&s, r, INFINITY, &h))
        continue;
      for (int li = 0; li < s.n_lights; li++) {
        vec3s l;
        float dist;
        light_incident(&s.lights[li], h.p, h.p_err, &l, &dist);
        if (!(glms_vec3_dot(h.n, l) > 0.0f) || dist == 0.0f)
          continue; /* behind the surface: the light adds nothing either way */
        vec3s got = shade_incident(&s, &s.lights[li], &h, &l);
        bool unclear;
        bool want = lecture_visible(&s, &h, l, dist, &unclear);
        if (unclear) {
          unclear_count++;
          continue;
        }
        compared++;
        lit += want;
        CHECK_THAT(&c, want != vec_is_zero(got),
                   "random scene %u, %s light in direction l = (%.6g, %.6g, %.6g) from "
                   "p = (%.6g, %.6g, %.6g) on a %s\n  expected %s (the lecture's closest-hit "
                   "ray, in long double)\n  got      %s", config,
                   li ? "directional" : "point", l.x, l.y, l.z,
                   h.p.x, h.p.y, h.p.z, h.inst->shape == SHAPE_PLANE ? "plane" : "sphere",
                   want ? "lit" : "blocked", vec_is_zero(got) ? "blocked" : "lit");
      }
    }
    scene_free(&s);
  }
  CHECK_DONE(&c);
  /* Enough of both answers for the comparison to mean something. */
  Check pre = CHECK("sphere_hit_t, plane_hit_t, light_incident",
                    "docs/04-phong.md, \"What you write\"");
  CHECK_REQUIRE(&pre, compared > 10000 && lit > 2000 && compared - lit > 2000,
                "the random scenes gave only %d points lit by a light in front of them (%d lit, "
                "%d too close to call), where about 34000 are expected: the camera rays' hits "
                "(step 02) or the lights' directions (step 04) are wrong; fix `make test-step 2` "
                "and `4` first", compared, lit, unclear_count);
}
