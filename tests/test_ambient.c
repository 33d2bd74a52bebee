/* Unit tests of step 06: the ambient term m_amb * l_amb, its default (the
 * diffuse colour), its skipping when zero, the point lights the camera sees
 * (P / t^2) and their shapes casting no shadow. docs/06-ambient.md. */
#include "check.h"

#include "app/parser.h"
#include "scene.h"
#include "shade.h"
#include "shapes.h"

#define DOC "docs/06-ambient.md, \"What you write\""
#define RELIES "shade_phong_light (step 04), shade_visible (step 05), sphere_hit_t, " \
               "plane_hit_t (step 02)"

static const unsigned STEP06 = SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS | SCENE_AMBIENT |
                               SCENE_LIGHT_SHAPES;

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
  cr_assert(floor, "the test's scene has no plane");
  Hit h = {.t = 1.0f, .p = vec_make(0.0f, 0.0f, 0.0f), .n = vec_make(0.0f, 1.0f, 0.0f),
           .p_err = 0.0f, .material = floor->material, .light = floor->light, .inst = floor};
  return h;
}

static void load(Scene *s, const char *text, unsigned features)
{
  scene_init(s);
  cr_assert(parser_load_string("test", text, s), "scene text rejected:\n%s", text);
  cr_assert(scene_prepare(s, features), "out of memory");
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
  cr_assert(s.info.ambient, "scene_prepare (given code): info.ambient not set");
  vec3s want = product(vec_make(0.3f, 0.9f, 0.55f), vec_make(0.2f, 0.4f, 0.7f));
  Check c = CHECK_RELYING("shade_phong", DOC, RELIES);
  const char *what[] = {"the sphere from outside", "the floor from above",
                        "the floor from below", "the sphere from inside"};
  /* Every point of every object: the same colour, whatever the geometry. */
  const Ray rays[] = {
      {.o = vec_make(0.0f, 1.0f, 2.0f), .d = vec_make(0.0f, 0.0f, -1.0f)},   /* the sphere */
      {.o = vec_make(0.0f, 1.0f, 2.0f), .d = vec_make(0.0f, -1.0f, 0.0f)},   /* the floor */
      {.o = vec_make(0.0f, -1.0f, 2.0f), .d = vec_make(0.0f, 1.0f, 0.0f)},   /* floor from below */
      {.o = vec_make(0.0f, 1.0f, -3.0f), .d = vec_make(0.6f, 0.0f, 0.8f)},   /* sphere from inside */
  };
  for (int k = 0; k < 4; k++)
    CHECK_VEC(&c, want, shade_trace(&s, rays[k]), 0.0, "no lights, l_amb = (0.2, 0.4, "
              "0.7), m_amb = (0.3, 0.9, 0.55), %s: m_amb * l_amb", what[k]);
  CHECK_DONE(&c);
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
  /* 0.25 * (0.5, 1, 0.25) + 0.5 = (0.625, 0.75, 0.5625): all exact in binary. */
  Check c = CHECK_RELYING("shade_phong", DOC, RELIES);
  CHECK_VEC(&c, vec_make(0.625f, 0.75f, 0.5625f),
            shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f)), 0.0,
            "floor point under a light (diffuse term 0.5), m_amb = 0.25, l_amb = (0.5, 1, "
            "0.25): m_amb * l_amb + the light's term");
  scene_free(&s);
}

Test(ambient, zero_ambient_is_skipped_and_gives_exactly_the_lights)
{
  /* No ambient statement: l_amb = 0. */
  Scene s;
  load(&s, lamp_scene, STEP06);
  Check g = CHECK("scene_prepare (given code)", "docs/06-ambient.md, \"The math\"");
  CHECK_INT(&g, 0, s.info.ambient, "no ambient statement (l_amb = 0): info.ambient");
  Hit h = floor_hit(&s);
  Check c = CHECK_RELYING("shade_phong", DOC, RELIES);
  CHECK_VEC(&c, vec_make(0.5f, 0.5f, 0.5f), shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f)),
            0.0, "floor point under a light (diffuse term 0.5), no ambient statement: the "
            "light's term alone");
  scene_free(&s);
  /* l_amb set, but every material's ambient colour is zero. */
  load(&s,
       "ambient 1 1 1\n"
       "material m ambient 0 0 0 diffuse 0.5 0.5 0.5\n"
       "plane point 0 0 0 normal 0 1 0 material m\n"
       "light point position 0 4 0 power 16 16 16\n",
       STEP06);
  CHECK_INT(&g, 0, s.info.ambient, "l_amb = 1 but m_amb = 0 everywhere: info.ambient");
  h = floor_hit(&s);
  CHECK_VEC(&c, vec_make(0.5f, 0.5f, 0.5f), shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f)),
            0.0, "the same with l_amb = 1 and m_amb = 0: the light's term alone");
  scene_free(&s);
  /* A step without SCENE_AMBIENT (step 05) drops l_amb and says so. */
  load(&s, "ambient 1 1 1\nmaterial m diffuse 0.5 0.5 0.5\n", SCENE_CAMERA | SCENE_LIGHTS);
  CHECK_THAT(&g, !s.info.ambient && (s.info.ignored & SCENE_AMBIENT) && vec_is_zero(s.ambient),
             "a step without ambient light: l_amb dropped and reported as ignored");
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
  Check g = CHECK("parser_load_string (given code)", "docs/06-ambient.md, \"The math\"");
  CHECK_VEC(&g, m[0].diffuse, m[0].ambient, 0.0, "a material without ambient: ambient = diffuse");
  CHECK_VEC(&g, vec_make(0, 0, 0), m[1].ambient, 0.0, "an explicit ambient 0 0 0 stays zero");
  CHECK_VEC(&g, vec_make(0.1f, 0.2f, 0.4f), m[2].ambient, 0.0, "an explicit ambient is kept");
  /* No light: the floor shows 0.5 * diffuse, exactly (a halving). */
  Ray down = {.o = vec_make(0.0f, 1.0f, 0.0f), .d = vec_make(0.0f, -1.0f, 0.0f)};
  Check c = CHECK_RELYING("shade_phong", DOC, RELIES);
  CHECK_VEC(&c, vec_make(0.15f, 0.3f, 0.45f), shade_trace(&s, down), 0.0,
            "no lights, l_amb = 0.5, a material whose ambient defaults to its diffuse "
            "(0.3, 0.6, 0.9): m_amb * l_amb");
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
  /* Along -z from the origin: the sphere of radius 0.5 at distance 10 is met
   * at t = 9.5, t^2 = 90.25 exactly; one correctly rounded division. Not
   * l_amb + P / t^2 as the lecture's slide writes (docs/06-ambient.md). */
  Ray r = {.o = vec_make(0.0f, 0.0f, 0.0f), .d = vec_make(0.0f, 0.0f, -1.0f)};
  vec3s c = shade_trace(&s, r);
  Check ck = CHECK_RELYING("shade_trace", DOC, "sphere_hit_t (step 02)");
  const long double p[3] = {50.0L, 100.0L, 200.0L};
  static const char *const names[3] = {"red", "green", "blue"};
  /* P / t^2 or P * (1 / t^2): the last bits are free, 4 ulps. */
  for (int k = 0; k < 3; k++)
    CHECK_ULPS(&ck, (float)(p[k] / 90.25L), c.raw[k], 4, "camera ray into a point light's "
               "sphere (radius 0.5, 10 away: t = 9.5) of power (50, 100, 200): P / t^2, %s",
               names[k]);
  /* From (1, 2, 3) toward the centre (1, 5, 7): distance 5, radius 1, t = 4:
   * P / 16 up to the float rounding of the direction (0, 0.6, 0.8). */
  r = (Ray){.o = vec_make(1.0f, 2.0f, 3.0f), .d = glms_vec3_normalize(vec_make(0.0f, 3.0f, 4.0f))};
  c = shade_trace(&s, r);
  for (int k = 0; k < 3; k++)
    CHECK_REL(&ck, (double)(p[k] / 16.0L), c.raw[k], 1e-6, "camera ray from 4 away into a "
              "light's sphere: P / 16, %s", names[k]);
  /* A light without radius has no shape: the ray toward it sees the background. */
  r = (Ray){.o = vec_make(0.0f, 0.0f, 0.0f), .d = glms_vec3_normalize(vec_make(1.0f, 1.0f, 1.0f))};
  CHECK_VEC(&ck, vec_make(0.2f, 0.3f, 0.4f), shade_trace(&s, r), 0.0,
            "camera ray toward a point light without radius (no shape): the background");
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
  Check c = CHECK_RELYING("shade_phong", DOC, RELIES);
  CHECK_VEC(&c, vec_make(1.0f, 1.0f, 1.0f), shade_phong(&s, &h, vec_make(0.0f, 3.0f, 3.0f)),
            0.0, "floor point under two lights, each 0.5, one light's sphere on both shadow "
            "rays (a light's shape casts no shadow): the sum");
  /* The spheres are there: the camera looking down the axis sees A's at t = 1.5. */
  Ray down = {.o = vec_make(0.0f, 6.0f, 0.0f), .d = vec_make(0.0f, -1.0f, 0.0f)};
  Check t = CHECK_RELYING("shade_trace", DOC, "sphere_hit_t (step 02)");
  CHECK_ULPS(&t, (float)(16.0L / 2.25L), shade_trace(&s, down).x, 4,
             "camera ray into the same light's sphere at t = 1.5: P / t^2");
  scene_free(&s);
}
