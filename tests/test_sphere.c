/* Unit tests of ray-sphere intersection (step 02): each root case, rays from
 * inside, spheres behind, tmax, normals facing the ray. docs/02-intersection.md. */
#include "check.h"
#include "sphere.h"

#define DOC "docs/02-intersection.md, \"What you write\""

static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz)
{
  Ray r = {.o = vec_make(ox, oy, oz), .d = glms_vec3_normalize(vec_make(dx, dy, dz))};
  return r;
}

/* Unit sphere 5 units down -z: a ray from the origin along -z meets it at
 * t = 4 and t = 6. */
static const Sphere S = {.center = {.x = 0.0f, .y = 0.0f, .z = -5.0f}, .radius = 1.0f};

Test(sphere, two_roots_gives_the_nearest)
{
  Check c = CHECK("sphere_hit_t", DOC);
  float t = sphere_hit_t(&S, ray(0, 0, 0, 0, 0, -1), INFINITY);
  CHECK_NEAR(&c, 4.0, t, 0.0, "ray from the origin along -z, unit sphere centred at z = -5 "
             "(roots 4 and 6): t");
  Check f = CHECK("sphere_hit_fill", DOC);
  Hit h;
  sphere_hit_fill(&S, ray(0, 0, 0, 0, 0, -1), 4.0f, &h);
  CHECK_NEAR(&f, 4.0, h.t, 0.0, "the same ray at t = 4: hit.t");
  CHECK_VEC(&f, vec_make(0.0f, 0.0f, -4.0f), h.p, 0.0, "the same ray at t = 4: hit.p");
  CHECK_VEC(&f, vec_make(0.0f, 0.0f, 1.0f), h.n, 0.0, "the same ray at t = 4: hit.n");
  CHECK_INT(&f, 0, h.backface, "the same ray at t = 4, from outside: hit.backface");
}

Test(sphere, oblique_hit_matches_the_long_double_quadratic)
{
  Sphere s = {.center = vec_make(0.5f, 0.1f, -6.0f), .radius = 1.3f};
  Ray r = ray(0.3f, -0.2f, 0.0f, 0.1f, 0.2f, -1.0f);
  /* |o + t d - c|^2 = R^2: t^2 + 2 (f.d) t + f.f - R^2 = 0, f = o - c, from
   * the float inputs in long double. */
  long double f[3] = {(long double)r.o.x - s.center.x, (long double)r.o.y - s.center.y,
                      (long double)r.o.z - s.center.z};
  long double d[3] = {r.d.x, r.d.y, r.d.z};
  long double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  long double b = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
  long double c = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - (long double)s.radius * s.radius;
  long double t0 = (-b - sqrtl(b * b - dd * c)) / dd;
  Check ct = CHECK("sphere_hit_t", DOC);
  float t = sphere_hit_t(&s, r, INFINITY);
  CHECK_REL(&ct, (double)t0, t, 1e-5, "oblique ray toward a sphere of radius 1.3 about 6 "
            "units away: t against the quadratic solved in long double");
  Check fill = CHECK("sphere_hit_fill", DOC);
  Hit h;
  sphere_hit_fill(&s, r, (float)t0, &h);
  vec3s rel = glms_vec3_sub(h.p, s.center);
  CHECK_NEAR(&fill, s.radius, glms_vec3_norm(rel), 4e-7, "the same hit: |p - c| (p on the sphere)");
  CHECK_NEAR(&fill, 1.0, glms_vec3_norm(h.n), 1e-6, "the same hit: |n|");
  CHECK_THAT(&fill, glms_vec3_dot(h.n, r.d) < 0.0f,
             "the same hit: n must face the ray (n.d < 0), got n.d = %.9g",
             glms_vec3_dot(h.n, r.d));
  CHECK_INT(&fill, 0, h.backface, "the same hit, from outside: hit.backface");
}

Test(sphere, tangent_ray_touches_once)
{
  /* The line x = 1 grazes the unit sphere at (1, 0, -5): discriminant 0. */
  Check c = CHECK("sphere_hit_t", DOC);
  float t = sphere_hit_t(&S, ray(1, 0, 0, 0, 0, -1), INFINITY);
  CHECK_NEAR(&c, 5.0, t, 0.0, "ray x = 1 along -z grazing the unit sphere at z = -5 "
             "(discriminant 0): t");
}

Test(sphere, miss_returns_infinity)
{
  Check c = CHECK("sphere_hit_t", DOC);
  CHECK_NEAR(&c, INFINITY, sphere_hit_t(&S, ray(1.001f, 0, 0, 0, 0, -1), INFINITY), 0.0,
             "ray x = 1.001 along -z, just outside the unit sphere at z = -5: a miss is INFINITY");
  CHECK_NEAR(&c, INFINITY, sphere_hit_t(&S, ray(0, 0, 0, 0, 1, 0), INFINITY), 0.0,
             "ray from the origin along +y, sphere at z = -5: a miss is INFINITY");
  CHECK_NEAR(&c, INFINITY, sphere_hit_t(&S, ray(0, 0, 0, 1, 0, -1), INFINITY), 0.0,
             "ray from the origin 45 degrees off the sphere's direction: a miss is INFINITY");
}

Test(sphere, origin_inside_hits_the_far_side_from_behind)
{
  /* From the centre, the sphere is 1 away in every direction. */
  Ray r = ray(0, 0, -5, 0, 1, 0);
  Check c = CHECK("sphere_hit_t", DOC);
  CHECK_NEAR(&c, 1.0, sphere_hit_t(&S, r, INFINITY), 0.0,
             "ray from the centre of the unit sphere along +y (roots -1 and 1): t");
  /* Off-centre inside: from (0, 0, -5.5), the far side at t = 0.5 or 1.5. */
  CHECK_NEAR(&c, 0.5, sphere_hit_t(&S, ray(0, 0, -5.5f, 0, 0, -1), INFINITY), 0.0,
             "ray from (0, 0, -5.5), inside, along -z: t");
  CHECK_NEAR(&c, 1.5, sphere_hit_t(&S, ray(0, 0, -5.5f, 0, 0, 1), INFINITY), 0.0,
             "ray from (0, 0, -5.5), inside, along +z: t");
  Check f = CHECK("sphere_hit_fill", DOC);
  Hit h;
  sphere_hit_fill(&S, r, 1.0f, &h);
  CHECK_INT(&f, 1, h.backface, "ray from the centre along +y, at t = 1 (it leaves the "
            "sphere): hit.backface");
  CHECK_VEC(&f, vec_make(0.0f, -1.0f, 0.0f), h.n, 0.0,
            "the same hit: n, flipped to face the ray");
  CHECK_VEC(&f, vec_make(0.0f, 1.0f, -5.0f), h.p, 0.0, "the same hit: p");
}

Test(sphere, behind_the_origin_is_not_hit)
{
  Check c = CHECK("sphere_hit_t", DOC);
  CHECK_NEAR(&c, INFINITY, sphere_hit_t(&S, ray(0, 0, 0, 0, 0, 1), INFINITY), 0.0,
             "ray from the origin along +z, sphere behind it (roots -6 and -4): a miss");
}

Test(sphere, tmax_is_respected)
{
  Ray r = ray(0, 0, 0, 0, 0, -1);
  Check c = CHECK("sphere_hit_t", DOC);
  CHECK_NEAR(&c, INFINITY, sphere_hit_t(&S, r, 3.0f), 0.0,
             "hit at t = 4 with tmax = 3: a miss");
  CHECK_NEAR(&c, INFINITY, sphere_hit_t(&S, r, 4.0f), 0.0,
             "hit at t = 4 with tmax = 4 (t must be < tmax, not <=): a miss");
  CHECK_NEAR(&c, 4.0, sphere_hit_t(&S, r, 4.5f), 0.0, "hit at t = 4 with tmax = 4.5: t");
  CHECK_NEAR(&c, INFINITY, sphere_hit_t(&S, ray(0, 0, -5, 0, 0, -1), 0.5f), 0.0,
             "from the centre, far side at t = 1, tmax = 0.5: a miss");
}

Test(sphere, normal_always_faces_the_ray)
{
  /* Rays from many directions toward and from inside the sphere. */
  Sphere s = {.center = vec_make(1.0f, 2.0f, 3.0f), .radius = 2.0f};
  Check ct = CHECK("sphere_hit_t", DOC), f = CHECK("sphere_hit_fill", DOC);
  for (int k = 0; k < 100; k++) {
    float a = 0.37f * (float)k, b = 0.11f * (float)k;
    vec3s d = glms_vec3_normalize(vec_make(cosf(a) * cosf(b), sinf(b), sinf(a) * cosf(b)));
    vec3s o_out = glms_vec3_sub(s.center, glms_vec3_scale(d, 10.0f));
    vec3s o_in = glms_vec3_add(s.center, glms_vec3_scale(d, 0.5f * (float)(k % 3) - 0.5f));
    Ray rays[2] = {{o_out, d}, {o_in, d}};
    for (int q = 0; q < 2; q++) {
      const char *from = q == 0 ? "from outside" : "from inside";
      float t_want = q == 0 ? 8.0f : 2.0f - (0.5f * (float)(k % 3) - 0.5f);
      float t = sphere_hit_t(&s, rays[q], INFINITY);
      CHECK_NEAR(&ct, t_want, t, 1e-5, "ray %d %s toward the centre of a sphere of radius 2: t",
                 k, from);
      Hit h;
      sphere_hit_fill(&s, rays[q], t_want, &h);
      CHECK_THAT(&f, glms_vec3_dot(h.n, d) < 0.0f, "ray %d %s: n must face the ray (n.d < 0), "
                 "got n.d = %.9g", k, from, glms_vec3_dot(h.n, d));
      CHECK_INT(&f, q == 1, h.backface, "ray %d %s: hit.backface", k, from);
    }
  }
  CHECK_DONE(&ct);
  CHECK_DONE(&f);
}

Test(sphere, p_err_bounds_the_hit_points_error)
{
  /* Spheres far from the origin and near it: p_err must be positive, at least
   * the distance of the refined p from the exact intersection (computed in
   * long double from the float inputs), and no more than 2^-20 (max|c| + r)
   * (a larger bound pushes shadow rays visibly off the surface). */
  Check f = CHECK("sphere_hit_fill", DOC);
  const float scales[] = {1.0f, 1e3f, 1e5f};
  for (int k = 0; k < 3; k++) {
    float d0 = scales[k];
    Sphere s = {.center = vec_make(0.3f * d0, 0.2f * d0, -d0), .radius = 0.25f * d0};
    Ray r = ray(0.01f * d0, 0.0f, 0.5f * d0, 0.3f, 0.19f, -1.5f);
    long double o[3] = {r.o.x, r.o.y, r.o.z}, d[3] = {r.d.x, r.d.y, r.d.z};
    long double c[3] = {s.center.x, s.center.y, s.center.z}, fo[3], b = 0, cc = 0, dd = 0;
    for (int a = 0; a < 3; a++) {
      fo[a] = o[a] - c[a];
      b += fo[a] * d[a];
      cc += fo[a] * fo[a];
      dd += d[a] * d[a];
    }
    cc -= (long double)s.radius * s.radius;
    long double t = (-b - sqrtl(b * b - dd * cc)) / dd, err = 0;
    Hit h;
    sphere_hit_fill(&s, r, (float)t, &h);
    for (int a = 0; a < 3; a++)
      err = fmaxl(err, fabsl((long double)h.p.raw[a] - (o[a] + t * d[a])));
    float cap = 0x1p-20f * (vec_max_abs(s.center) + s.radius);
    CHECK_THAT(&f, h.p_err > 0.0f && (long double)h.p_err >= err && h.p_err <= cap,
               "sphere of radius %g at distance %g: hit.p_err must bound p's error and stay "
               "small\n  expected %.9Lg <= p_err <= %.9g (p_err > 0)\n  got      p_err = %.9g",
               (double)s.radius, (double)d0, err, (double)cap, (double)h.p_err);
  }
  CHECK_DONE(&f);
}

Test(sphere, normal_of_a_sphere_far_from_the_origin)
{
  /* Step 05 shades spheres 1000 radii from the origin seen from a few radii
   * (stress test 4): the highlight there needs the normal to the last bits,
   * and p's coordinates are rounded to ulps of |c|, 1000 times those of the
   * radius. The normal must be the direction of (o - c) + t d (the point of
   * the ray at the given t, seen from the centre; long double from the float
   * inputs) within 16 x 2^-24 (1 + |o - c| / r): its error may grow with the
   * ray's distance from the sphere, not with the sphere's from the origin. */
  Check f = CHECK("sphere_hit_fill", DOC);
  const float away[] = {1.0f, 1e3f, 1e5f};
  double worst = 0.0;
  for (int k = 0; k < 3; k++) {
    for (int q = 0; q < 64; q++) {
      float a = 0.37f * (float)q + 0.2f * (float)k, b = 0.23f * (float)q;
      vec3s u = glms_vec3_normalize(vec_make(cosf(a) * cosf(b), sinf(b), sinf(a) * cosf(b)));
      vec3s side = glms_vec3_normalize(glms_vec3_cross(u, vec_make(0.3f, 0.9f, -0.2f)));
      float radius = 0.25f * (float)(1 + q % 5);
      Sphere s = {.center = glms_vec3_scale(vec_make(0.6f, -0.48f, 0.64f), away[k] * radius),
                  .radius = radius};
      float dist = radius * (1.5f + 0.5f * (float)(q % 9));
      vec3s o = glms_vec3_add(s.center, glms_vec3_scale(u, dist));
      vec3s aimed = glms_vec3_add(s.center, glms_vec3_scale(side, radius * 0.1f * (float)(q % 9)));
      Ray r = {.o = o, .d = glms_vec3_normalize(glms_vec3_sub(aimed, o))};
      /* The nearest root in long double, rounded to float: t is not
       * sphere_hit_t's here. */
      long double fo[3], d[3], fb = 0, ff = 0, dd = 0;
      for (int i = 0; i < 3; i++) {
        fo[i] = (long double)r.o.raw[i] - s.center.raw[i];
        d[i] = r.d.raw[i];
        fb += fo[i] * d[i];
        ff += fo[i] * fo[i];
        dd += d[i] * d[i];
      }
      long double disc = fb * fb - dd * (ff - (long double)radius * radius);
      cr_assert(disc > 0.0L, "the test's own ray %d must hit its sphere", q);
      float t = (float)((-fb - sqrtl(disc)) / dd);
      long double rel[3], len = 0;
      for (int i = 0; i < 3; i++) {
        rel[i] = fo[i] + (long double)t * d[i];
        len += rel[i] * rel[i];
      }
      len = sqrtl(len);
      Hit h;
      sphere_hit_fill(&s, r, t, &h);
      double err = 0.0;
      for (int i = 0; i < 3; i++)
        err = fmax(err, (double)fabsl((long double)h.n.raw[i] - rel[i] / len));
      double units = err / 0x1p-24, bound = 16.0 * (1.0 + (double)(sqrtl(ff) / radius));
      worst = fmax(worst, units / bound);
      CHECK_THAT(&f, units <= bound, "sphere of radius %g, %g radii from the origin, ray %d "
                 "from %.3g radii away: the normal is %.3g x 2^-24 off the direction of "
                 "(o - c) + t d (at most %.3g asked): form p - c as (o - c) + t d; p's "
                 "coordinates are rounded to ulps of |c|, %g times those of r\n  expected "
                 "n = (%.9Lg, %.9Lg, %.9Lg)\n  got      n = (%.9g, %.9g, %.9g)",
                 (double)radius, (double)away[k], q, (double)(sqrtl(ff) / radius), units, bound,
                 (double)away[k], rel[0] / len, rel[1] / len, rel[2] / len, h.n.x, h.n.y, h.n.z);
    }
  }
  CHECK_DONE(&f);
  cr_log_info("sphere_hit_fill: worst normal error %.3g of the bound", worst);
}
