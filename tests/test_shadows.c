/* Unit tests of step 05's shadow test (shade_visible, ray_spawn, through
 * shade_incident and shade_phong): occluders in front of, behind and beside
 * the light, self-shadowing, grazing occluders decided in long double,
 * directional lights, ray_spawn's offset (the lecture's closest-hit method as
 * the reference: tests/test_shadows_lecture.c). Correctness tests accept any
 * correct solution (the lecture's closest-hit ray too, for every light); the
 * saving the doc asks for (no shadow ray for a light behind the surface) is a
 * test of its own. docs/05-shadows.md, "What you write". */
#include "check.h"
#include "rng.h"
#include "shadow.h"
#include "shadow_scene.h"

/* The hit the floor plane y = 0 (the scene's only plane) gives at (x, 0, z)
 * seen from above: what plane_hit_fill returns there (an axis plane snaps p
 * exactly, p_err = 0). scene_prepare may reorder instances: look it up. */
static Hit floor_hit(const Scene *s, float x, float z)
{
  const Instance *floor = NULL;
  for (int k = 0; k < s->n_instances && !floor; k++)
    if (s->instances[k].shape == SHAPE_PLANE)
      floor = &s->instances[k];
  cr_assert(floor, "the test's scene has no plane");
  Hit h = {.t = 1.0f, .p = vec_make(x, 0.0f, z), .n = vec_make(0.0f, 1.0f, 0.0f),
           .p_err = 0.0f, .backface = false, .material = floor->material,
           .light = floor->light, .inst = floor};
  return h;
}

/* Step 05's answer for light k at hit h, and the shadow rays it traced. */
static vec3s incident(const Scene *s, int k, const Hit *h, uint64_t *rays)
{
  CountingTable t;
  Scene c = counted(s, &t);
  vec3s l;
  vec3s li = shade_incident(&c, &c.lights[k], h, &l);
  *rays = (uint64_t)t.queries;
  return li;
}

/* Floor point at the origin, light (0, 4, 0) of power (16, 32, 48): unshadowed
 * L_i = P / 4^2 = (1, 2, 3) exactly. */
static void lamp_scene(Scene *s)
{
  scene_start(s);
  add_plane(s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  add_point(s, vec_make(0.0f, 4.0f, 0.0f), vec_make(16.0f, 32.0f, 48.0f));
}

/* Lit: L_i = (1, 2, 3) within a few ulps (P / r^2 leaves the last bits free);
 * blocked: exactly zero. */
static void check_lamp(vec3s occluder, float radius, bool lit, const char *what)
{
  Scene s;
  lamp_scene(&s);
  add_sphere(&s, occluder, radius);
  prepare(&s);
  Hit h = floor_hit(&s, 0.0f, 0.0f);
  uint64_t rays;
  vec3s li = incident(&s, 0, &h, &rays);
  Check c = shadow_check();
  if (lit)
    CHECK_THAT(&c, fabsf(li.x - 1.0f) <= 4e-7f && fabsf(li.y - 2.0f) <= 8e-7f &&
                   fabsf(li.z - 3.0f) <= 8e-7f,
               "floor point under a light 4 above, %s: the light is visible\n"
               "  expected L_i = (1, 2, 3)\n  got      L_i = (%.9g, %.9g, %.9g)", what,
               li.x, li.y, li.z);
  else
    CHECK_THAT(&c, vec_is_zero(li),
               "floor point under a light 4 above, %s: the light is blocked\n"
               "  expected L_i = (0, 0, 0)\n  got      L_i = (%.9g, %.9g, %.9g)", what,
               li.x, li.y, li.z);
  scene_free(&s);
}

Test(shadows, occluder_between_point_and_light_blocks_it)
{
  check_lamp(vec_make(0.0f, 2.0f, 0.0f), 0.5f, false, "sphere at y in [1.5, 2.5]");
  check_lamp(vec_make(0.3f, 3.0f, -0.2f), 0.5f, false, "sphere off-centre, on the segment");
}

Test(shadows, occluder_behind_the_light_does_not)
{
  check_lamp(vec_make(0.0f, 6.0f, 0.0f), 1.0f, true, "sphere at y in [5, 7], past the light");
  /* Near surface at y = 4.1: 0.1 past the light. */
  check_lamp(vec_make(0.0f, 4.5f, 0.0f), 0.4f, true, "sphere at y in [4.1, 4.9], past the light");
}

Test(shadows, light_inside_a_closed_object_is_blocked)
{
  /* The sphere's surface at y = 3.9 lies between the point and the light. */
  check_lamp(vec_make(0.0f, 4.5f, 0.0f), 0.6f, false,
             "light inside a sphere at y in [3.9, 5.1]");
}

Test(shadows, occluder_on_the_other_side_of_the_point_does_not)
{
  /* On the shadow ray's line but at t < 0 (below the floor). */
  check_lamp(vec_make(0.0f, -2.0f, 0.0f), 1.0f, true, "sphere at y in [-3, -1], below the floor");
}

Test(shadows, occluder_beside_the_segment_does_not)
{
  check_lamp(vec_make(1.0f, 2.0f, 0.0f), 0.9f, true, "sphere 0.1 beside the segment");
}

/* Long double: does the open segment (p, q) meet the sphere (c, r)? *margin is
 * the distance of the configuration from the boundary between the answers
 * (tangency, or an end of the segment on the surface). */
static bool segment_meets_sphere(vec3s p, vec3s q, vec3s c, float r, long double *margin)
{
  long double u[3], f[3], len = 0.0L, tc = 0.0L, f2 = 0.0L;
  for (int a = 0; a < 3; a++) {
    u[a] = (long double)q.raw[a] - p.raw[a];
    f[a] = (long double)c.raw[a] - p.raw[a];
    len += u[a] * u[a];
  }
  len = sqrtl(len);
  for (int a = 0; a < 3; a++) {
    tc += f[a] * u[a] / len;
    f2 += f[a] * f[a];
  }
  long double h = sqrtl(fmaxl(0.0L, f2 - tc * tc)); /* centre to the line */
  *margin = fabsl(h - r);
  if (h >= r)
    return false;
  long double half = sqrtl((long double)r * r - h * h);
  long double t0 = tc - half, t1 = tc + half;
  long double ends[4] = {t0, t1, t0 - len, t1 - len};
  for (int k = 0; k < 4; k++)
    *margin = fminl(*margin, fabsl(ends[k]));
  return t1 > 0.0L && t0 < len;
}

/* Floor point at the origin, light at (2, 6, 3) (distance 7). The sphere of
 * radius 0.5 sits at distance `along` on the segment's line, pushed `aside`
 * off it along u = (3, 0, -2)/sqrt(13), which is perpendicular to the line. */
static void check_grazing(long double along, long double aside, const char *what)
{
  const long double d[3] = {2.0L / 7, 6.0L / 7, 3.0L / 7};
  const long double u[3] = {3.0L / sqrtl(13.0L), 0.0L, -2.0L / sqrtl(13.0L)};
  vec3s c;
  for (int a = 0; a < 3; a++)
    c.raw[a] = (float)(along * d[a] + aside * u[a]);
  Scene s;
  scene_start(&s);
  add_plane(&s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  vec3s light = vec_make(2.0f, 6.0f, 3.0f);
  add_point(&s, light, vec_make(49.0f, 49.0f, 49.0f));
  add_sphere(&s, c, 0.5f);
  prepare(&s);
  long double margin;
  bool blocked = segment_meets_sphere(vec_make(0.0f, 0.0f, 0.0f), light, c, 0.5f, &margin);
  /* Far above the float errors of the ray (a few 1e-7 over 7 units) and the
   * 2^-20 relative slack of the step's tmax (7e-6). */
  cr_assert(margin > 1e-4L, "%s: the test's own geometry is too close to call", what);
  Hit h = floor_hit(&s, 0.0f, 0.0f);
  uint64_t rays;
  vec3s li = incident(&s, 0, &h, &rays);
  Check ck = shadow_check();
  CHECK_THAT(&ck, vec_is_zero(li) == blocked,
             "floor point, light 7 away, sphere of radius 0.5 with its %s (%.2Lg from the "
             "boundary, decided in long double)\n  expected %s\n  got      %s (L_i = %.9g)",
             what, margin, blocked ? "blocked" : "lit", vec_is_zero(li) ? "blocked" : "lit",
             li.x);
  scene_free(&s);
}

Test(shadows, grazing_occluders_are_decided_as_the_exact_geometry_says)
{
  check_grazing(3.5L, 0.5L + 1e-3L, "silhouette 1e-3 beside the ray");
  check_grazing(3.5L, 0.5L - 1e-3L, "silhouette 1e-3 across the ray");
  check_grazing(7.0L + 0.5L + 1e-3L, 0.0L, "near surface 1e-3 past the light");
  check_grazing(7.0L + 0.5L - 1e-3L, 0.0L, "near surface 1e-3 before the light");
  check_grazing(-0.5L - 1e-3L, 0.0L, "far surface 1e-3 behind the point");
  check_grazing(7.0L - 0.5L, 0.5L - 1e-3L, "silhouette across the ray next to the light");
}

/* A random vector with components in [-0.5, 0.5), drawn x, y, z in turn. */
static vec3s centred(Rng *rng)
{
  float x = rng_float(rng) - 0.5f, y = rng_float(rng) - 0.5f, z = rng_float(rng) - 0.5f;
  return vec_make(x, y, z);
}

/* Random hits on the surface of `s`'s instance 0 seen from outside; every one
 * whose normal faces the light must be lit (a convex shape cannot shadow its
 * own lit side: |r n + t w|^2 = r^2 + 2 t r n.w + t^2 |w|^2 > r^2 when
 * n.w > 0). n.l below 1e-6 is too close to call from float data. */
static void check_not_self_shadowed(Scene *s, vec3s centre, float size, const char *what)
{
  Rng rng = rng_make(5, 0, 0);
  int lit = 0, grazing = 0;
  Check c = CHECK_RELYING("ray_spawn, shade_visible", SPAWN_DOC, RELIES);
  for (int k = 0; k < 20000; k++) {
    vec3s dir = centred(&rng);
    vec3s eye = glms_vec3_add(centre, glms_vec3_scale(glms_vec3_normalize(dir), 10.0f * size));
    vec3s aim = centred(&rng);
    vec3s target = glms_vec3_add(centre, glms_vec3_scale(aim, 1.9f * size));
    Ray r = {.o = eye, .d = glms_vec3_normalize(glms_vec3_sub(target, eye))};
    Hit h;
    if (!scene_intersect(s, r, INFINITY, &h))
      continue;
    vec3s l;
    vec3s li = shade_incident(s, &s->lights[0], &h, &l);
    float n_dot_l = glms_vec3_dot(h.n, l);
    if (!(n_dot_l > 1e-6f))
      continue;
    lit++;
    grazing += n_dot_l < 0.02f;
    CHECK_THAT(&c, !vec_is_zero(li), "%s of size %g at (%g, %g, %g), a point on its lit side "
               "(n.l = %.3g) at p = (%.9g, %.9g, %.9g), p_err = %.3g: shadowed by its own "
               "surface (shadow acne)\n  expected lit\n  got      blocked", what, size,
               centre.x, centre.y, centre.z, n_dot_l, h.p.x, h.p.y, h.p.z, h.p_err);
  }
  CHECK_DONE(&c);
  Check hits = CHECK("sphere_hit_t, plane_hit_t", "docs/02-intersection.md, \"What you write\"");
  CHECK_REQUIRE(&hits, lit > 3000 && grazing > 20, "20000 rays at a %s found only %d lit points "
                "(%d grazing) where most should hit it: fix `make test-step 2` first", what,
                lit, grazing);
}

Test(shadows, sphere_lit_from_outside_is_not_self_shadowed)
{
  const vec3s centres[] = {vec_make(0.0f, 1.0f, 0.0f), vec_make(1000.0f, 500.0f, -2000.0f),
                           vec_make(3e-3f, 1e-3f, 0.0f)};
  const float radii[] = {1.0f, 2.0f, 1e-3f};
  for (int k = 0; k < 3; k++) {
    Scene s;
    scene_start(&s);
    add_sphere(&s, centres[k], radii[k]);
    add_point(&s, glms_vec3_add(centres[k], vec_make(2.0f * radii[k], 5.0f * radii[k], 0.0f)),
              vec_make(1.0f, 1.0f, 1.0f));
    prepare(&s);
    check_not_self_shadowed(&s, centres[k], radii[k], "sphere");
    scene_free(&s);
  }
}

Test(shadows, point_on_a_plane_is_not_shadowed_by_the_plane)
{
  /* An axis plane (p snapped exactly) and tilted planes (p_err > 0) at two
   * scales, the light on the front side. */
  const vec3s points[] = {vec_make(0.0f, 0.0f, 0.0f), vec_make(0.3f, -0.2f, 0.1f),
                          vec_make(1000.0f, 2000.0f, -500.0f)};
  const vec3s normals[] = {vec_make(0.0f, 1.0f, 0.0f), vec_make(1.0f, 3.0f, 2.0f),
                           vec_make(-2.0f, 5.0f, 1.0f)};
  const float sizes[] = {1.0f, 1.0f, 100.0f};
  for (int k = 0; k < 3; k++) {
    Scene s;
    scene_start(&s);
    add_plane(&s, points[k], normals[k]);
    vec3s n = glms_vec3_normalize(normals[k]);
    /* The light low over the plane (3 along it, 0.05 above), so that many
     * shadow rays leave nearly parallel to it: n.l from about 0.01 to 0.03. */
    vec3s side = glms_vec3_normalize(vec_make(n.y, -n.x, 0.0f));
    vec3s off = glms_vec3_add(glms_vec3_scale(side, 3.0f), glms_vec3_scale(n, 0.05f));
    vec3s light = glms_vec3_add(points[k], glms_vec3_scale(off, sizes[k]));
    add_point(&s, light, vec_make(1.0f, 1.0f, 1.0f));
    prepare(&s);
    check_not_self_shadowed(&s, points[k], sizes[k], "plane");
    scene_free(&s);
  }
}

Test(shadows, directional_light_is_blocked_at_any_distance)
{
  Scene s;
  scene_start(&s);
  add_plane(&s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  /* Light travelling along -(1, 2, 1): toward the light is (1, 2, 1)/sqrt(6). */
  add_directional(&s, vec_make(-1.0f, -2.0f, -1.0f), vec_make(0.25f, 0.5f, 0.75f));
  const long double k = 1000.0L / sqrtl(6.0L);
  add_sphere(&s, vec_make((float)k, (float)(2 * k), (float)k), 1.0f); /* 1000 away, on the ray */
  add_sphere(&s, vec_make(5.0f, 1.0f, -5.0f), 1.0f);                  /* off the ray */
  prepare(&s);
  uint64_t rays;
  Hit h = floor_hit(&s, 0.0f, 0.0f);
  vec3s li = incident(&s, 0, &h, &rays);
  Check c = shadow_check();
  CHECK_VEC(&c, vec_make(0, 0, 0), li, 0.0, "directional light, a sphere on the shadow ray "
            "1000 away (a directional light is infinitely far): L_i");
  /* From (2, 0, 0) the ray passes the far sphere's centre 2 sqrt(5/6) = 1.83
   * away (> radius 1), and the near one's 5.9 away: E arrives unchanged. */
  h = floor_hit(&s, 2.0f, 0.0f);
  li = incident(&s, 0, &h, &rays);
  CHECK_VEC(&c, vec_make(0.25f, 0.5f, 0.75f), li, 0.0, "directional light, the far sphere "
            "1.83 beside the shadow ray (radius 1): L_i = E");
  scene_free(&s);
}

Test(shadows, phong_adds_only_the_unblocked_lights)
{
  Scene s;
  scene_start(&s);
  add_plane(&s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  add_point(&s, vec_make(0.0f, 4.0f, 0.0f), vec_make(16.0f, 16.0f, 16.0f)); /* L 1, n.l 1 */
  add_point(&s, vec_make(3.0f, 4.0f, 0.0f), vec_make(25.0f, 25.0f, 25.0f)); /* L 1, n.l 0.8 */
  add_sphere(&s, vec_make(1.5f, 2.0f, 0.0f), 0.5f); /* centred on the second segment */
  prepare(&s);
  Hit h = floor_hit(&s, 0.0f, 0.0f);
  Check c = CHECK_RELYING("shade_visible, ray_spawn (through shade_phong)", DOC,
                          "shade_phong_light, light_incident (step 04), sphere_hit_t, "
                          "plane_hit_t (step 02)");
  /* 0.5 * 1 * 1 from the first light; the second (0.5 * 0.8 = 0.4) is blocked. */
  CHECK_VEC(&c, vec_make(0.5f, 0.5f, 0.5f), shade_phong(&s, &h, vec_make(0.0f, 5.0f, 5.0f)),
            1e-6, "floor point lit by a light above (0.5) and blocked from a second (0.4): "
            "shade_phong, the first light's term alone");
  /* shade_trace from above the floor at (0, 0, 0). */
  Ray r = {.o = vec_make(0.0f, 2.0f, 2.0f), .d = glms_vec3_normalize(vec_make(0.0f, -1.0f, -1.0f))};
  CHECK_VEC(&c, vec_make(0.5f, 0.5f, 0.5f), shade_trace(&s, r), 1e-6,
            "the same point seen by a camera ray: shade_trace");
  scene_free(&s);
}

Test(saving, no_shadow_ray_behind_the_surface)
{
  /* The saving the doc asks for: a light behind the surface adds nothing
   * (n.l <= 0), so it needs no shadow ray. A solution that traces one anyway
   * is correct and passes every other test; this one counts the rays, and
   * tests/run.sh reports it as a saving (WARN), not as a failure. */
  Scene s;
  scene_start(&s);
  add_plane(&s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  add_point(&s, vec_make(0.0f, -4.0f, 0.0f), vec_make(1.0f, 1.0f, 1.0f));          /* below */
  add_point(&s, vec_make(4.0f, 0.0f, 0.0f), vec_make(1.0f, 1.0f, 1.0f));           /* n.l = 0 */
  add_directional(&s, vec_make(0.0f, 1.0f, 0.0f), vec_make(1.0f, 1.0f, 1.0f));     /* upward */
  prepare(&s);
  Hit h = floor_hit(&s, 0.0f, 0.0f);
  const char *what[] = {"a point light below the surface",
                        "a point light in its tangent plane (n.l = 0)",
                        "a directional light shining upward"};
  Check c = CHECK("shade_incident, shade_visible", "docs/05-shadows.md, \"What you write\"");
  for (int k = 0; k < 3; k++) {
    uint64_t rays;
    incident(&s, k, &h, &rays);
    CHECK_INT(&c, 0, rays, "floor point, %s: shadow rays traced (queries of the scene)", what[k]);
  }
  scene_free(&s);
}

/* ray_spawn's offset along n, (o - p).n, in long double. */
static long double spawn_offset(const Hit *h, Ray r)
{
  long double off = 0.0L;
  for (int a = 0; a < 3; a++)
    off += ((long double)r.o.raw[a] - h->p.raw[a]) * h->n.raw[a];
  return off;
}

Test(shadows, spawn_leaves_the_surface_past_the_error_box_on_the_side_of_the_direction)
{
  /* The origin moves along n by between |n|_1 p_err (out of the box of
   * possible exact points) and 8 |n|_1 p_err (the doc's 2, with room), toward
   * the side dir goes to; dir is kept. At three scales: no fixed epsilon fits
   * all of them. */
  const struct {
    vec3s p, n;
    float p_err;
  } hits[] = {
      {{.x = 0.0f, .y = 1.0f, .z = 0.0f}, {.x = 0.0f, .y = 1.0f, .z = 0.0f}, 1e-6f},
      {{.x = 3e-5f, .y = 1e-4f, .z = -2e-5f}, {.x = 1.0f / 3, .y = 2.0f / 3, .z = 2.0f / 3}, 3e-11f},
      {{.x = 1e4f, .y = -2e4f, .z = 5e3f}, {.x = 0.6f, .y = 0.0f, .z = -0.8f}, 5e-3f},
  };
  Check c = CHECK("ray_spawn", SPAWN_DOC);
  for (int k = 0; k < 3; k++) {
    Hit h = {.t = 1.0f, .p = hits[k].p, .n = hits[k].n, .p_err = hits[k].p_err,
             .material = 0, .light = -1};
    float n1 = vec_sum_abs(h.n);
    for (int side = 0; side < 2; side++) {
      vec3s dir = side == 0 ? glms_vec3_normalize(glms_vec3_add(h.n, vec_make(0.1f, 0, 0)))
                            : glms_vec3_negate(h.n);
      Ray r = ray_spawn(&h, dir);
      long double off = spawn_offset(&h, r) * (side == 0 ? 1.0L : -1.0L);
      CHECK_THAT(&c, off > (long double)n1 * h.p_err && off <= 8.0L * n1 * h.p_err,
                 "hit at (%g, %g, %g) with p_err = %g, direction %s the surface: the origin's "
                 "offset along n toward that side\n  expected between %.3g and %.3g "
                 "(|n|_1 p_err .. 8 |n|_1 p_err)\n  got      %.9Lg", h.p.x, h.p.y, h.p.z,
                 h.p_err, side == 0 ? "leaving" : "entering", (double)(n1 * h.p_err),
                 (double)(8.0f * n1 * h.p_err), off);
      CHECK_VEC(&c, dir, r.d, 0.0, "the same spawned ray: its direction is dir, unchanged");
    }
  }
  CHECK_DONE(&c);
}
