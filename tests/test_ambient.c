/* Unit tests of step 06: the ambient term m_amb * l_amb, its default (the
 * diffuse colour), its skipping when zero, the point lights the camera sees
 * (P / t^2) and their shapes casting no shadow. docs/06-ambient.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "app/parser.h"
#include "shade.h"

static const unsigned STEP06 = SCENE_CAMERA | SCENE_LIGHTS | SCENE_AMBIENT | SCENE_LIGHT_SHAPES;

static bool vec_eq(vec3s a, vec3s b)
{
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* The float nearest to a * b (one rounding, what a float product gives). */
static vec3s product(vec3s a, vec3s b)
{
  return vec_make((float)((long double)a.x * b.x), (float)((long double)a.y * b.y),
                  (float)((long double)a.z * b.z));
}

/* Floor y = 0 of material 0, seen from above at the origin (plane_hit_fill's
 * hit there: p exact, p_err 0). */
static Hit floor_hit(const Scene *s)
{
  const Instance *floor = NULL;
  for (int k = 0; k < s->n_instances && !floor; k++)
    if (s->instances[k].shape == SHAPE_PLANE)
      floor = &s->instances[k];
  cr_assert(floor);
  Hit h = {.t = 1.0f, .p = vec_make(0.0f, 0.0f, 0.0f), .n = vec_make(0.0f, 1.0f, 0.0f),
           .p_err = 0.0f, .inst = floor};
  return h;
}

static void load(Scene *s, const char *text, unsigned features)
{
  scene_init(s);
  cr_assert(parser_load_string("test", text, s), "scene text rejected:\n%s", text);
  cr_assert(scene_prepare(s, features));
}

Test(ambient, alone_is_m_amb_times_l_amb)
{
  Scene s;
  load(&s,
       "ambient 0.2 0.4 0.7\n"
       "material m ambient 0.3 0.9 0.55 diffuse 0.8 0.1 0.6 specular 1 1 1 shininess 8\n"
       "plane point 0 0 0 normal 0 1 0 material m\n"
       "sphere center 0 1 -3 radius 1 material m\n",
       STEP06);
  cr_expect(s.info.ambient);
  vec3s want = product(vec_make(0.3f, 0.9f, 0.55f), vec_make(0.2f, 0.4f, 0.7f));
  RenderCtx ctx = {0};
  /* Every point of every object: the same colour, whatever the geometry. */
  const Ray rays[] = {
      {.o = vec_make(0.0f, 1.0f, 2.0f), .d = vec_make(0.0f, 0.0f, -1.0f)},   /* the sphere */
      {.o = vec_make(0.0f, 1.0f, 2.0f), .d = vec_make(0.0f, -1.0f, 0.0f)},   /* the floor */
      {.o = vec_make(0.0f, -1.0f, 2.0f), .d = vec_make(0.0f, 1.0f, 0.0f)},   /* floor from below */
      {.o = vec_make(0.0f, 1.0f, -3.0f), .d = vec_make(0.6f, 0.0f, 0.8f)},   /* sphere from inside */
  };
  for (int k = 0; k < 4; k++) {
    ctx.rays = 0;
    vec3s c = shade_trace(&s, rays[k], &ctx);
    cr_expect(vec_eq(c, want), "ray %d: (%a, %a, %a), expected (%a, %a, %a)", k, c.x, c.y, c.z,
              want.x, want.y, want.z);
    cr_expect(ctx.rays == 1, "ray %d: %llu rays, expected 1 (no lights)", k,
              (unsigned long long)ctx.rays);
  }
  scene_free(&s);
}

/* Floor of diffuse 0.5 and ambient 0.25 at the origin, light (0, 4, 0) of
 * power 16: diffuse 0.5 * (16 / 4^2) * (n.l = 1) = 0.5, ambient 0.25 * l_amb. */
static const char lamp_scene[] =
    "material m ambient 0.25 0.25 0.25 diffuse 0.5 0.5 0.5\n"
    "plane point 0 0 0 normal 0 1 0 material m\n"
    "light point position 0 4 0 power 16 16 16\n";

Test(ambient, ambient_and_one_light_add_exactly)
{
  char text[512];
  snprintf(text, sizeof text, "ambient 0.5 1 0.25\n%s", lamp_scene);
  Scene s;
  load(&s, text, STEP06);
  Hit h = floor_hit(&s);
  RenderCtx ctx = {0};
  vec3s c = shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f), &ctx);
  /* 0.25 * (0.5, 1, 0.25) + 0.5 = (0.625, 0.75, 0.5625): all exact in binary. */
  cr_expect(vec_eq(c, vec_make(0.625f, 0.75f, 0.5625f)), "(%g, %g, %g)", c.x, c.y, c.z);
  cr_expect(ctx.rays == 1, "%llu shadow rays, expected 1", (unsigned long long)ctx.rays);
  scene_free(&s);
}

Test(ambient, zero_ambient_is_skipped_and_gives_exactly_the_lights)
{
  /* No ambient statement: l_amb = 0. */
  Scene s;
  load(&s, lamp_scene, STEP06);
  cr_expect(!s.info.ambient, "info.ambient set with l_amb = 0");
  Hit h = floor_hit(&s);
  RenderCtx ctx = {0};
  vec3s c = shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f), &ctx);
  cr_expect(vec_eq(c, vec_make(0.5f, 0.5f, 0.5f)), "(%g, %g, %g), expected 0.5", c.x, c.y, c.z);
  scene_free(&s);
  /* l_amb set, but every material's ambient colour is zero. */
  load(&s,
       "ambient 1 1 1\n"
       "material m ambient 0 0 0 diffuse 0.5 0.5 0.5\n"
       "plane point 0 0 0 normal 0 1 0 material m\n"
       "light point position 0 4 0 power 16 16 16\n",
       STEP06);
  cr_expect(!s.info.ambient, "info.ambient set with m_amb = 0 everywhere");
  h = floor_hit(&s);
  c = shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f), &ctx);
  cr_expect(vec_eq(c, vec_make(0.5f, 0.5f, 0.5f)), "(%g, %g, %g), expected 0.5", c.x, c.y, c.z);
  scene_free(&s);
  /* A step without SCENE_AMBIENT (step 05) drops l_amb and says so. */
  load(&s, "ambient 1 1 1\nmaterial m diffuse 0.5 0.5 0.5\n", SCENE_CAMERA | SCENE_LIGHTS);
  cr_expect(!s.info.ambient && (s.info.ignored & SCENE_AMBIENT) && vec_is_zero(s.ambient));
  scene_free(&s);
}

Test(ambient, material_ambient_defaults_to_diffuse)
{
  Scene s;
  load(&s,
       "ambient 0.5 0.5 0.5\n"
       "material plain diffuse 0.3 0.6 0.9\n"
       "material dark  diffuse 0.3 0.6 0.9 ambient 0 0 0\n"
       "material other ambient 0.1 0.2 0.4 diffuse 0.3 0.6 0.9\n"
       "plane point 0 0 0 normal 0 1 0 material plain\n",
       STEP06);
  const Material *m = s.materials;
  cr_expect(vec_eq(m[0].ambient, m[0].diffuse), "no ambient given: ambient = diffuse");
  cr_expect(vec_is_zero(m[1].ambient), "an explicit ambient 0 0 0 stays zero");
  cr_expect(vec_eq(m[2].ambient, vec_make(0.1f, 0.2f, 0.4f)), "an explicit ambient is kept");
  /* No light: the floor shows 0.5 * diffuse, exactly (a halving). */
  Ray down = {.o = vec_make(0.0f, 1.0f, 0.0f), .d = vec_make(0.0f, -1.0f, 0.0f)};
  RenderCtx ctx = {0};
  vec3s c = shade_trace(&s, down, &ctx);
  cr_expect(vec_eq(c, vec_make(0.15f, 0.3f, 0.45f)), "(%g, %g, %g)", c.x, c.y, c.z);
  scene_free(&s);
}

Test(ambient, camera_sees_a_point_light_as_p_over_t_squared)
{
  Scene s;
  load(&s,
       "ambient 0.1 0.1 0.1\n"
       "background 0.2 0.3 0.4\n"
       "light point position 0 0 -10 power 50 100 200 radius 0.5\n"
       "light point position 1 5 7 power 50 100 200 radius 1\n"
       "light point position 9 9 9 power 1 1 1\n",
       STEP06);
  RenderCtx ctx = {0};
  /* Along -z from the origin: the sphere of radius 0.5 at distance 10 is met
   * at t = 9.5, t^2 = 90.25 exactly; one correctly rounded division. Not
   * l_amb + P / t^2 as the lecture's slide writes (docs/06-ambient.md). */
  Ray r = {.o = vec_make(0.0f, 0.0f, 0.0f), .d = vec_make(0.0f, 0.0f, -1.0f)};
  vec3s c = shade_trace(&s, r, &ctx);
  vec3s want = vec_make((float)(50.0L / 90.25L), (float)(100.0L / 90.25L),
                        (float)(200.0L / 90.25L));
  cr_expect(vec_eq(c, want), "(%a, %a, %a), expected (%a, %a, %a)", c.x, c.y, c.z, want.x,
            want.y, want.z);
  /* From (1, 2, 3) toward the centre (1, 5, 7): distance 5, radius 1, t = 4:
   * P / 16 up to the float rounding of the direction (0, 0.6, 0.8). */
  r = (Ray){.o = vec_make(1.0f, 2.0f, 3.0f), .d = glms_vec3_normalize(vec_make(0.0f, 3.0f, 4.0f))};
  c = shade_trace(&s, r, &ctx);
  cr_expect(fabsf(c.x / 3.125f - 1.0f) < 1e-6f && fabsf(c.z / 12.5f - 1.0f) < 1e-6f,
            "(%g, %g, %g), expected (3.125, 6.25, 12.5)", c.x, c.y, c.z);
  /* A light without radius has no shape: the ray toward it sees the background. */
  r = (Ray){.o = vec_make(0.0f, 0.0f, 0.0f), .d = glms_vec3_normalize(vec_make(1.0f, 1.0f, 1.0f))};
  c = shade_trace(&s, r, &ctx);
  cr_expect(vec_eq(c, vec_make(0.2f, 0.3f, 0.4f)), "(%g, %g, %g): background expected", c.x,
            c.y, c.z);
  scene_free(&s);
}

Test(ambient, lights_shapes_never_cast_shadows)
{
  /* Light A's sphere (radius 0.5 around (0, 4, 0)) lies on the shadow ray of
   * light B at (0, 8, 0), and on A's own shadow ray. Both still light the
   * floor: 0.5 * (16 / 16) + 0.5 * (64 / 64) = 1. */
  Scene s;
  load(&s,
       "material m diffuse 0.5 0.5 0.5 ambient 0 0 0\n"
       "plane point 0 0 0 normal 0 1 0 material m\n"
       "light point position 0 4 0 power 16 16 16 radius 0.5\n"
       "light point position 0 8 0 power 64 64 64 radius 0.5\n",
       STEP06);
  Hit h = floor_hit(&s);
  RenderCtx ctx = {0};
  vec3s c = shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f), &ctx);
  cr_expect(vec_eq(c, vec_make(1.0f, 1.0f, 1.0f)), "(%g, %g, %g), expected 1", c.x, c.y, c.z);
  /* The spheres are there: the camera looking down the axis sees A's at t = 1.5. */
  Ray down = {.o = vec_make(0.0f, 6.0f, 0.0f), .d = vec_make(0.0f, -1.0f, 0.0f)};
  c = shade_trace(&s, down, &ctx);
  cr_expect(vec_eq(c, vec_make(16.0f / 2.25f, 16.0f / 2.25f, 16.0f / 2.25f)),
            "(%g, %g, %g), expected 16 / 1.5^2", c.x, c.y, c.z);
  scene_free(&s);
}
