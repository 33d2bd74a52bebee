/* Unit tests of step 05's shadow test (shade_incident): occluders in front of,
 * behind and beside the light, self-shadowing, grazing occluders decided in
 * long double, directional lights, and the lecture's closest-hit version as
 * the reference for the any-hit one. docs/05-shadows.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "rng.h"
#include "shade.h"

/* A scene with one white diffuse material (index 0). */
static void scene_start(Scene *s)
{
  scene_init(s);
  Material m = {.name = "white", .ambient = vec_make(0.5f, 0.5f, 0.5f),
                .diffuse = vec_make(0.5f, 0.5f, 0.5f)};
  cr_assert(scene_add_material(s, &m));
}

static void add_sphere(Scene *s, vec3s c, float r)
{
  Instance in = {.shape = SHAPE_SPHERE, .sphere = {.center = c, .radius = r},
                 .material = 0, .light = -1};
  cr_assert(scene_add_instance(s, &in));
}

static void add_plane(Scene *s, vec3s point, vec3s normal)
{
  Instance in = {.shape = SHAPE_PLANE, .plane = plane_make(point, normal),
                 .material = 0, .light = -1};
  cr_assert(scene_add_instance(s, &in));
}

static void add_point(Scene *s, vec3s pos, vec3s power)
{
  Light l = {.type = LIGHT_POINT, .position = pos, .power = power};
  cr_assert(scene_add_light(s, &l));
}

static void add_directional(Scene *s, vec3s dir, vec3s irradiance)
{
  Light l = {.type = LIGHT_DIRECTIONAL, .direction = glms_vec3_normalize(dir),
             .irradiance = irradiance};
  cr_assert(scene_add_light(s, &l));
}

static void prepare(Scene *s)
{
  cr_assert(scene_prepare(s, SCENE_CAMERA | SCENE_LIGHTS));
}

/* The hit the floor plane y = 0 (the scene's only plane) gives at (x, 0, z)
 * seen from above: what plane_hit_fill returns there (an axis plane snaps p
 * exactly, p_err = 0). scene_prepare may reorder instances: look it up. */
static Hit floor_hit(const Scene *s, float x, float z)
{
  const Instance *floor = NULL;
  for (int k = 0; k < s->n_instances && !floor; k++)
    if (s->instances[k].shape == SHAPE_PLANE)
      floor = &s->instances[k];
  cr_assert(floor);
  Hit h = {.t = 1.0f, .p = vec_make(x, 0.0f, z), .n = vec_make(0.0f, 1.0f, 0.0f),
           .p_err = 0.0f, .backface = false, .inst = floor};
  return h;
}

/* Step 05's answer for light k at hit h, and the shadow rays it traced. */
static vec3s incident(const Scene *s, int k, const Hit *h, uint64_t *rays)
{
  RenderCtx ctx = {0};
  vec3s l;
  vec3s li = shade_incident(s, &s->lights[k], h, &l, &ctx);
  *rays = ctx.rays;
  return li;
}

static bool vec_eq(vec3s a, vec3s b)
{
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* Floor point at the origin, light (0, 4, 0) of power (16, 32, 48): unshadowed
 * L_i = P / 4^2 = (1, 2, 3) exactly. */
static void lamp_scene(Scene *s)
{
  scene_start(s);
  add_plane(s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  add_point(s, vec_make(0.0f, 4.0f, 0.0f), vec_make(16.0f, 32.0f, 48.0f));
}

static void check_lamp(vec3s occluder, float radius, bool lit, const char *what)
{
  Scene s;
  lamp_scene(&s);
  add_sphere(&s, occluder, radius);
  prepare(&s);
  Hit h = floor_hit(&s, 0.0f, 0.0f);
  uint64_t rays;
  vec3s li = incident(&s, 0, &h, &rays);
  vec3s want = lit ? vec_make(1.0f, 2.0f, 3.0f) : glms_vec3_zero();
  cr_expect(vec_eq(li, want), "%s: L_i = (%g, %g, %g), expected (%g, %g, %g)", what,
            li.x, li.y, li.z, want.x, want.y, want.z);
  cr_expect(rays == 1, "%s: %llu shadow rays, expected 1", what, (unsigned long long)rays);
  scene_free(&s);
}

Test(shadows, occluder_between_point_and_light_blocks_it)
{
  check_lamp(vec_make(0.0f, 2.0f, 0.0f), 0.5f, false, "sphere at y in [1.5, 2.5]");
  check_lamp(vec_make(0.3f, 3.0f, -0.2f), 0.5f, false, "sphere off-centre, on the segment");
}

Test(shadows, occluder_behind_the_light_does_not)
{
  check_lamp(vec_make(0.0f, 6.0f, 0.0f), 1.0f, true, "sphere at y in [5, 7]");
  /* Near surface at y = 4.1: 0.1 past the light. */
  check_lamp(vec_make(0.0f, 4.5f, 0.0f), 0.4f, true, "sphere at y in [4.1, 4.9]");
}

Test(shadows, light_inside_a_closed_object_is_blocked)
{
  /* The sphere's surface at y = 3.9 lies between the point and the light. */
  check_lamp(vec_make(0.0f, 4.5f, 0.0f), 0.6f, false, "light inside [3.9, 5.1]");
}

Test(shadows, occluder_on_the_other_side_of_the_point_does_not)
{
  /* On the shadow ray's line but at t < 0 (below the floor). */
  check_lamp(vec_make(0.0f, -2.0f, 0.0f), 1.0f, true, "sphere at y in [-3, -1]");
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
  cr_expect(vec_is_zero(li) == blocked, "%s: expected %s (margin %Lg), got L_i = %g", what,
            blocked ? "blocked" : "lit", margin, li.x);
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

/* Random hits on the surface of `s`'s instance 0 seen from outside; every one
 * whose normal faces the light must be lit (a convex shape cannot shadow its
 * own lit side: |r n + t w|^2 = r^2 + 2 t r n.w + t^2 |w|^2 > r^2 when
 * n.w > 0). n.l below 1e-6 is too close to call from float data. */
static void check_not_self_shadowed(Scene *s, vec3s centre, float size, const char *what)
{
  Rng rng = rng_make(5, 0, 0);
  int lit = 0, grazing = 0;
  for (int k = 0; k < 20000; k++) {
    vec3s dir = vec_make(rng_float(&rng) - 0.5f, rng_float(&rng) - 0.5f, rng_float(&rng) - 0.5f);
    vec3s eye = glms_vec3_add(centre, glms_vec3_scale(glms_vec3_normalize(dir), 10.0f * size));
    vec3s aim = vec_make(rng_float(&rng) - 0.5f, rng_float(&rng) - 0.5f, rng_float(&rng) - 0.5f);
    vec3s target = glms_vec3_add(centre, glms_vec3_scale(aim, 1.9f * size));
    Ray r = {.o = eye, .d = glms_vec3_normalize(glms_vec3_sub(target, eye))};
    Hit h;
    if (!scene_intersect(s, r, INFINITY, &h))
      continue;
    cr_assert(h.inst == &s->instances[0]);
    RenderCtx ctx = {0};
    vec3s l;
    vec3s li = shade_incident(s, &s->lights[0], &h, &l, &ctx);
    float n_dot_l = glms_vec3_dot(h.n, l);
    if (!(n_dot_l > 1e-6f))
      continue;
    lit++;
    grazing += n_dot_l < 0.02f;
    cr_expect(!vec_is_zero(li), "%s: self-shadowed at (%a, %a, %a), n.l = %g", what, h.p.x,
              h.p.y, h.p.z, n_dot_l);
    if (vec_is_zero(li))
      break;
  }
  cr_expect(lit > 3000 && grazing > 20, "%s: only %d lit points, %d grazing", what, lit, grazing);
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
  cr_expect(vec_is_zero(li) && rays == 1, "under the far sphere: L_i = %g, %llu rays", li.x,
            (unsigned long long)rays);
  /* From (2, 0, 0) the ray passes the far sphere's centre 2 sqrt(5/6) = 1.83
   * away (> radius 1), and the near one's 5.9 away: E arrives unchanged. */
  h = floor_hit(&s, 2.0f, 0.0f);
  li = incident(&s, 0, &h, &rays);
  cr_expect(vec_eq(li, vec_make(0.25f, 0.5f, 0.75f)) && rays == 1,
            "beside it: L_i = (%g, %g, %g)", li.x, li.y, li.z);
  scene_free(&s);
}

Test(shadows, no_shadow_ray_for_a_light_behind_the_surface)
{
  Scene s;
  scene_start(&s);
  add_plane(&s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  add_point(&s, vec_make(0.0f, -4.0f, 0.0f), vec_make(1.0f, 1.0f, 1.0f));          /* below */
  add_point(&s, vec_make(4.0f, 0.0f, 0.0f), vec_make(1.0f, 1.0f, 1.0f));           /* n.l = 0 */
  add_directional(&s, vec_make(0.0f, 1.0f, 0.0f), vec_make(1.0f, 1.0f, 1.0f));     /* upward */
  add_point(&s, vec_make(0.0f, 4.0f, 0.0f), vec_make(1.0f, 1.0f, 1.0f));           /* above */
  prepare(&s);
  Hit h = floor_hit(&s, 0.0f, 0.0f);
  const uint64_t want[] = {0, 0, 0, 1};
  for (int k = 0; k < 4; k++) {
    uint64_t rays;
    incident(&s, k, &h, &rays);
    cr_expect(rays == want[k], "light %d: %llu shadow rays, expected %llu", k,
              (unsigned long long)rays, (unsigned long long)want[k]);
  }
  /* shade_phong: only the light above counts, 0.5 * (1/16) * 1. */
  RenderCtx ctx = {0};
  vec3s c = shade_phong(&s, &h, vec_make(0.0f, 1.0f, 1.0f), &ctx);
  cr_expect(vec_eq(c, vec_make(0.03125f, 0.03125f, 0.03125f)) && ctx.rays == 1,
            "shade_phong = %g with %llu rays, expected 0.03125 with 1", c.x,
            (unsigned long long)ctx.rays);
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
  RenderCtx ctx = {0};
  vec3s c = shade_phong(&s, &h, vec_make(0.0f, 5.0f, 5.0f), &ctx);
  /* 0.5 * 1 * 1 from the first light; the second (0.5 * 0.8 = 0.4) is blocked. */
  cr_expect(vec_eq(c, vec_make(0.5f, 0.5f, 0.5f)), "colour %g, expected 0.5 (0.9 unblocked)", c.x);
  cr_expect(ctx.rays == 2, "%llu shadow rays, expected 2", (unsigned long long)ctx.rays);
  /* shade_trace from above the floor at (0, 0, 0) adds the camera ray. */
  Ray r = {.o = vec_make(0.0f, 2.0f, 2.0f), .d = glms_vec3_normalize(vec_make(0.0f, -1.0f, -1.0f))};
  ctx.rays = 0;
  c = shade_trace(&s, r, &ctx);
  cr_expect(fabsf(c.x - 0.5f) < 1e-6f && ctx.rays == 3, "shade_trace = %g, %llu rays", c.x,
            (unsigned long long)ctx.rays);
  scene_free(&s);
}

/* The lecture's version, written out as the reference: trace the closest hit
 * along the shadow ray; the light is visible when nothing is hit, or when the
 * first hit lies beyond the light. *unclear when that hit is within 2^-18 of
 * the light's distance (the step stops 2^-20 short of it on purpose). */
static bool closest_hit_visible(const Scene *s, const Hit *h, vec3s l, float dist, bool *unclear)
{
  Hit first;
  *unclear = false;
  if (!scene_intersect(s, ray_spawn(h, l), INFINITY, &first))
    return true;
  *unclear = fabsf(first.t - dist) <= 0x1p-18f * dist;
  return first.t > dist;
}

/* Random spheres over a floor, a point and a directional light. */
static void random_scene(Scene *s, Rng *rng)
{
  scene_start(s);
  add_plane(s, vec_make(0.0f, 0.0f, 0.0f), vec_make(0.0f, 1.0f, 0.0f));
  for (int k = 0; k < 8; k++) {
    float r = 0.2f + 0.8f * rng_float(rng);
    add_sphere(s, vec_make(6.0f * rng_float(rng) - 3.0f, 2.5f * rng_float(rng),
                           6.0f * rng_float(rng) - 3.0f), r);
  }
  add_point(s, vec_make(8.0f * rng_float(rng) - 4.0f, 1.0f + 5.0f * rng_float(rng),
                        8.0f * rng_float(rng) - 4.0f), vec_make(10.0f, 10.0f, 10.0f));
  add_directional(s, vec_make(rng_float(rng) - 0.5f, -1.0f, rng_float(rng) - 0.5f),
                  vec_make(1.0f, 1.0f, 1.0f));
  prepare(s);
}

Test(shadows, any_hit_agrees_with_the_lectures_closest_hit_version)
{
  int compared = 0, lit = 0, unclear_count = 0, mismatches = 0;
  for (uint32_t config = 0; config < 40; config++) {
    Rng rng = rng_make(11, config, 0);
    Scene s;
    random_scene(&s, &rng);
    for (int k = 0; k < 500; k++) {
      vec3s eye = vec_make(0.0f, 4.0f, 10.0f);
      vec3s target = vec_make(8.0f * rng_float(&rng) - 4.0f, 2.0f * rng_float(&rng),
                              8.0f * rng_float(&rng) - 4.0f);
      Ray r = {.o = eye, .d = glms_vec3_normalize(glms_vec3_sub(target, eye))};
      Hit h;
      if (!scene_intersect(&s, r, INFINITY, &h))
        continue;
      for (int li = 0; li < s.n_lights; li++) {
        RenderCtx ctx = {0};
        vec3s l, l_ref;
        float dist;
        light_incident(&s.lights[li], h.p, h.p_err, &l_ref, &dist);
        vec3s got = shade_incident(&s, &s.lights[li], &h, &l, &ctx);
        if (!(glms_vec3_dot(h.n, l) > 0.0f) || dist == 0.0f)
          continue; /* no shadow ray: shade_phong skips this light */
        bool unclear;
        bool want = closest_hit_visible(&s, &h, l, dist, &unclear);
        if (unclear) {
          unclear_count++;
          continue;
        }
        compared++;
        lit += want;
        if (want == vec_is_zero(got) && mismatches++ < 5)
          cr_expect(false, "config %u light %d at (%g, %g, %g): lecture says %s", config, li,
                    h.p.x, h.p.y, h.p.z, want ? "lit" : "blocked");
      }
    }
    scene_free(&s);
  }
  cr_expect(mismatches == 0, "%d of %d shadow tests disagree", mismatches, compared);
  /* Enough of both answers for the comparison to mean something. */
  cr_expect(compared > 10000 && lit > 2000 && compared - lit > 2000,
            "compared %d (%d lit, %d unclear)", compared, lit, unclear_count);
}
