/* Unit tests of step 04's Phong regions (shade_phong_light, common/phong.c;
 * shade_phong, common/shade.c): hand-checkable configurations at the
 * origin with normal +y, in a scene with nothing that could cast a shadow.
 * docs/04-phong.md, "What you write". */
#include "check.h"
#include "phong.h"
#include "scene.h"
#include "shade.h"
#include "shapes.h"

#define DOC "docs/04-phong.md, \"What you write\""

/* Relative error allowed on a diffuse term: a few float roundings. */
static const double DIFFUSE_REL = 2e-6;

/* ... and on a term with the lobe (r.v)^shi: r.v = 1 - e gives about
 * 1 - shi e, so the float error of r.v grows with the exponent. */
static double lobe_rel(float shininess)
{
  return 2e-6 + 4e-7 * shininess;
}

/* A hit at the origin with normal +y, seen from above. */
static Hit floor_hit(const Instance *inst)
{
  Hit h = {.t = 1.0f, .p = vec_make(0, 0, 0), .n = vec_make(0, 1, 0), .p_err = 0.0f,
           .material = inst->material, .light = inst->light, .inst = inst};
  return h;
}

/* Unit vector of (x, y, z) given in long double, rounded once per component. */
static vec3s unit(long double x, long double y, long double z)
{
  long double n = sqrtl(x * x + y * y + z * z);
  return vec_make((float)(x / n), (float)(y / n), (float)(z / n));
}

static void check_rgb(Check *c, const double want[3], vec3s got, double rel, const char *what)
{
  static const char *const names[3] = {"red", "green", "blue"};
  for (int k = 0; k < 3; k++)
    CHECK_REL(c, want[k], got.raw[k], rel, "%s: %s", what, names[k]);
}

Test(phong, diffuse_along_the_normal_is_m_dif_times_l_i)
{
  /* n.l = 1: c = m_dif * L_i = (0.5, 0.25, 1) * (2, 1, 3). */
  Instance inst = {.material = 0, .light = -1};
  Hit h = floor_hit(&inst);
  Material m = {.diffuse = vec_make(0.5f, 0.25f, 1.0f)};
  vec3s c = shade_phong_light(&m, &h, unit(0, 1, 1), vec_make(2, 1, 3), vec_make(0, 1, 0));
  Check ck = CHECK("shade_phong_light", DOC);
  check_rgb(&ck, (double[3]){1.0, 0.25, 3.0}, c, DIFFUSE_REL,
            "light along the normal (n.l = 1), L_i = (2, 1, 3), m_dif = (0.5, 0.25, 1)");
}

Test(phong, diffuse_follows_the_cosine)
{
  /* l at 45 degrees: n.l = 1/sqrt(2). */
  Instance inst = {.material = 0, .light = -1};
  Hit h = floor_hit(&inst);
  Material m = {.diffuse = vec_make(1, 1, 1)};
  vec3s c = shade_phong_light(&m, &h, unit(0, 1, 0), vec_make(1, 2, 0.5f), unit(-1, 1, 0));
  long double k = 1.0L / sqrtl(2.0L);
  Check ck = CHECK("shade_phong_light", DOC);
  check_rgb(&ck, (double[3]){(double)k, (double)(2 * k), (double)(0.5L * k)}, c, DIFFUSE_REL,
            "light at 45 degrees (n.l = 0.7071), L_i = (1, 2, 0.5), m_dif = 1");
}

Test(phong, eye_on_the_reflection_gives_m_spe_times_l_i)
{
  /* l = (-1, 1, 0)/sqrt(2), r = reflect(-l, n) = (1, 1, 0)/sqrt(2) = v: r.v = 1,
   * so any shininess gives m_spe * L_i; twice the L_i, twice the highlight
   * (the lecture's slide omits L_i here; docs/04-phong.md says why not). */
  Instance inst = {.material = 0, .light = -1};
  Hit h = floor_hit(&inst);
  Material m = {.specular = vec_make(0.2f, 0.4f, 0.6f), .shininess = 50.0f};
  Check ck = CHECK("shade_phong_light", DOC);
  vec3s c = shade_phong_light(&m, &h, unit(1, 1, 0), vec_make(1, 2, 0.5f), unit(-1, 1, 0));
  check_rgb(&ck, (double[3]){0.2, 0.8, 0.3}, c, lobe_rel(50.0f),
            "eye on the reflection (r.v = 1), shininess 50, L_i = (1, 2, 0.5), m_spe = "
            "(0.2, 0.4, 0.6)");
  c = shade_phong_light(&m, &h, unit(1, 1, 0), vec_make(2, 4, 1), unit(-1, 1, 0));
  check_rgb(&ck, (double[3]){0.4, 1.6, 0.6}, c, lobe_rel(50.0f),
            "the same with L_i doubled to (2, 4, 1): the highlight doubles");
}

Test(phong, light_behind_the_surface_gives_zero)
{
  /* n.l < 0, and n.l = 0, even with the eye on the mirror direction. */
  Instance inst = {.material = 0, .light = -1};
  Hit h = floor_hit(&inst);
  Material m = {.diffuse = vec_make(1, 1, 1), .specular = vec_make(1, 1, 1), .shininess = 1.0f};
  Check ck = CHECK("shade_phong_light", DOC);
  const struct {
    vec3s l, v;
    const char *what;
  } cases[] = {
      {unit(0, -1, 0), unit(0, 1, 0), "light straight below the surface (n.l = -1)"},
      {unit(-1, -0.001L, 0), unit(1, 0.001L, 0), "light just below the horizon, eye on its "
                                                 "mirror direction"},
      {unit(-1, 0, 0), unit(1, 0, 0), "light on the horizon (n.l = 0)"},
  };
  for (int k = 0; k < 3; k++)
    check_rgb(&ck, (double[3]){0, 0, 0},
              shade_phong_light(&m, &h, cases[k].v, vec_make(100, 100, 100), cases[k].l), 0.0,
              cases[k].what);
  CHECK_DONE(&ck);
}

/* Light at 30 degrees over the horizon from -x: l = (-cos 30, sin 30, 0),
 * n.l = 0.5, r = (cos 30, sin 30, 0). m_dif = 0.2, m_spe = 1, L_i = 1. */
static vec3s lobe_shade(float shininess, vec3s v)
{
  Instance inst = {.material = 0, .light = -1};
  Hit h = floor_hit(&inst);
  Material m = {.diffuse = vec_make(0.2f, 0.2f, 0.2f), .specular = vec_make(1, 1, 1),
                .shininess = shininess};
  return shade_phong_light(&m, &h, v, vec_make(1, 1, 1), unit(-sqrtl(3.0L) / 2, 0.5L, 0));
}

Test(phong, lobe_is_cos_to_the_shininess_for_any_exponent)
{
  /* v = 0.5 r + (sqrt(3)/2) z: r.v = 0.5 (60 degrees from the reflection), so
   * the lobe is 0.5^shi, for whole, odd and fractional exponents. */
  const float shi[] = {0.0f, 0.5f, 1.0f, 2.5f, 3.0f, 8.0f, 17.0f};
  long double s3 = sqrtl(3.0L) / 2;
  vec3s v = unit(0.5L * s3, 0.25L, s3);
  Check ck = CHECK("shade_phong_light", DOC);
  for (size_t k = 0; k < sizeof shi / sizeof shi[0]; k++) {
    double want = 0.1 + pow(0.5, shi[k]);
    vec3s c = lobe_shade(shi[k], v);
    CHECK_REL(&ck, want, c.x, lobe_rel(shi[k]),
              "eye 60 degrees from the reflection (r.v = 0.5), shininess %g: "
              "0.2 (n.l = 0.5) + 0.5^%g", shi[k], shi[k]);
  }
  CHECK_DONE(&ck);
}

Test(phong, eye_past_the_lobe_sees_no_highlight)
{
  /* v = (-cos 30, sin 30, 0), the eye on the light's side: r.v = -0.5. The
   * lobe is max(0, r.v)^shi = 0; without the max, (-0.5)^shi would give
   * -0.5, -0.125 or NaN. Only the diffuse 0.2 * 0.5 remains. */
  const float shi[] = {1.0f, 2.0f, 2.5f, 3.0f, 0.5f, 7.0f};
  vec3s v = unit(-sqrtl(3.0L) / 2, 0.5L, 0);
  Check ck = CHECK("shade_phong_light", DOC);
  for (size_t k = 0; k < sizeof shi / sizeof shi[0]; k++)
    CHECK_REL(&ck, 0.1, lobe_shade(shi[k], v).x, DIFFUSE_REL,
              "eye on the light's side, past the lobe (r.v = -0.5), shininess %g: "
              "max(0, r.v)^%g = 0, so only the diffuse 0.1", shi[k], shi[k]);
  CHECK_DONE(&ck);
}

/* shade_phong's tests: a scene with the given lights, one material, and no
 * shape (nothing can shadow the hit, in every step that adds shadows). */
typedef struct Setup {
  Scene scene;
  Plane floor;
  Instance inst;
  Hit hit;
} Setup;

static void setup(Setup *s, Material m, const Light *lights, int n_lights)
{
  scene_init(&s->scene);
  cr_assert(scene_add_material(&s->scene, &m), "out of memory");
  for (int k = 0; k < n_lights; k++)
    cr_assert(scene_add_light(&s->scene, &lights[k]), "out of memory");
  cr_assert(scene_prepare(&s->scene, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  s->floor = plane_make(vec_make(0, 0, 0), vec_make(0, 1, 0));
  s->inst = (Instance){.shape = SHAPE_PLANE, .material = 0, .light = -1, .plane = s->floor};
  s->hit = floor_hit(&s->inst);
}

static Light point(float x, float y, float z, float pr, float pg, float pb)
{
  Light L = {.type = LIGHT_POINT, .position = vec_make(x, y, z), .power = vec_make(pr, pg, pb)};
  return L;
}

Test(phong, lights_add_up)
{
  /* Light 2 above (L_i = (8, 4, 12)/4, n.l = 1) plus one at (-3, 3, 0)
   * (L_i = (18, 36, 9)/18, n.l = 1/sqrt(2)), m_dif = (0.5, 0.25, 1). */
  Setup s;
  Light L[2] = {point(0, 2, 0, 8, 4, 12), point(-3, 3, 0, 18, 36, 9)};
  setup(&s, (Material){.diffuse = vec_make(0.5f, 0.25f, 1.0f)}, L, 2);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(0, 5, 5));
  double k = 1.0 / sqrt(2.0);
  Check ck = CHECK("shade_phong", DOC);
  check_rgb(&ck, (double[3]){1.0 + 0.5 * k, 0.25 + 0.5 * k, 3.0 + 0.5 * k}, c, DIFFUSE_REL,
            "two point lights, above and at 45 degrees: the sum of their terms");
  scene_free(&s.scene);
}

Test(phong, view_direction_is_toward_the_eye)
{
  /* The eye far out on the reflection of the light at (-3, 3, 0), at
   * (30, 30, 0): v = normalize(eye - p) = r, so c = m_spe * L_i. */
  Setup s;
  Light L = point(-3, 3, 0, 18, 36, 9);
  setup(&s, (Material){.specular = vec_make(0.2f, 0.4f, 0.6f), .shininess = 50.0f}, &L, 1);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(30, 30, 0));
  Check ck = CHECK("shade_phong", DOC);
  check_rgb(&ck, (double[3]){0.2, 0.8, 0.3}, c, lobe_rel(50.0f),
            "eye at (30, 30, 0) on the reflection of the light at (-3, 3, 0): "
            "v = normalize(eye - p), m_spe * L_i");
  scene_free(&s.scene);
}

Test(phong, directional_light)
{
  /* direction (0, -1, -1)/sqrt(2): l = (0, 1, 1)/sqrt(2), n.l = 1/sqrt(2);
   * c = m_dif * E / sqrt(2) with E = (1, 2, 3). */
  Setup s;
  Light L = {.type = LIGHT_DIRECTIONAL, .direction = unit(0, -1, -1),
             .irradiance = vec_make(1, 2, 3)};
  setup(&s, (Material){.diffuse = vec_make(0.5f, 0.5f, 1.0f)}, &L, 1);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(0, 5, 0));
  double k = 1.0 / sqrt(2.0);
  Check ck = CHECK("shade_phong", DOC);
  check_rgb(&ck, (double[3]){0.5 * k, k, 3.0 * k}, c, DIFFUSE_REL,
            "directional light from (0, 1, 1)/sqrt(2), E = (1, 2, 3), m_dif = (0.5, 0.5, 1)");
  scene_free(&s.scene);
}

Test(phong, lights_behind_the_surface_add_nothing)
{
  Setup s;
  Light L[2] = {point(0, -2, 0, 100, 100, 100), point(-3, -0.001f, 0, 100, 100, 100)};
  setup(&s, (Material){.diffuse = vec_make(1, 1, 1), .specular = vec_make(1, 1, 1),
                       .shininess = 1.0f}, L, 2);
  /* The eye even sits on the reflection of the second light. */
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(3, 0.001f, 0));
  Check ck = CHECK("shade_phong", DOC);
  check_rgb(&ck, (double[3]){0, 0, 0}, c, 0.0, "two point lights below the surface");
  scene_free(&s.scene);
}
