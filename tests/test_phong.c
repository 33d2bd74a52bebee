/* Unit tests of step 04's Phong shading (shade.o of the step): hand-checkable
 * configurations at the origin with normal +y. docs/04-phong.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "shade.h"

typedef struct Setup {
  Scene scene;
  Instance inst;
  Hit hit;
  RenderSettings set;
  RenderCtx ctx;
} Setup;

/* One material, the given lights; a hit at the origin with normal +y. */
static void setup(Setup *s, Material m, const Light *lights, int n_lights)
{
  scene_init(&s->scene);
  cr_assert(scene_add_material(&s->scene, &m));
  for (int k = 0; k < n_lights; k++)
    cr_assert(scene_add_light(&s->scene, &lights[k]));
  s->inst = (Instance){.shape = SHAPE_PLANE, .material = 0, .light = -1,
                       .plane = plane_make(vec_make(0, 0, 0), vec_make(0, 1, 0))};
  s->hit = (Hit){.t = 1.0f, .p = vec_make(0, 0, 0), .n = vec_make(0, 1, 0), .p_err = 0.0f,
                 .inst = &s->inst};
  s->set = (RenderSettings){.threads = 1, .seed = 1, .samples = 1, .light_samples = 1};
  s->ctx = (RenderCtx){.set = &s->set};
}

static bool near3(vec3s v, long double x, long double y, long double z)
{
  long double tol = 2e-6L * (1.0L + fabsl(x) + fabsl(y) + fabsl(z));
  return fabsl(v.x - x) <= tol && fabsl(v.y - y) <= tol && fabsl(v.z - z) <= tol;
}

/* Within `rel` of each expected value: r.v = 1 - e gives (1 - e)^shi, about
 * 1 - shi e, so a lobe's float error grows with the exponent. */
static bool near3_rel(vec3s v, long double x, long double y, long double z, long double rel)
{
  return fabsl(v.x - x) <= rel * x && fabsl(v.y - y) <= rel * y && fabsl(v.z - z) <= rel * z;
}

static Light point(float x, float y, float z, float pr, float pg, float pb)
{
  Light L = {.type = LIGHT_POINT, .position = vec_make(x, y, z), .power = vec_make(pr, pg, pb)};
  return L;
}

Test(phong, light_along_the_normal_gives_diffuse_times_p_over_r2)
{
  /* r = 2: L_i = (8, 4, 12) / 4 = (2, 1, 3); n.l = 1; c = m_dif * L_i. */
  Setup s;
  Light L = point(0, 2, 0, 8, 4, 12);
  setup(&s, (Material){.diffuse = vec_make(0.5f, 0.25f, 1.0f)}, &L, 1);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(0, 5, 5), &s.ctx);
  cr_expect(near3(c, 1.0L, 0.25L, 3.0L), "c = (%.9g %.9g %.9g)", c.x, c.y, c.z);
  scene_free(&s.scene);
}

Test(phong, diffuse_follows_the_cosine)
{
  /* Light at (-3, 3, 0): r^2 = 18, n.l = cos 45 = 1/sqrt(2), L_i = P / 18. */
  Setup s;
  Light L = point(-3, 3, 0, 18, 36, 9);
  setup(&s, (Material){.diffuse = vec_make(1, 1, 1)}, &L, 1);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(0, 5, 0), &s.ctx);
  long double k = 1.0L / sqrtl(2.0L);
  cr_expect(near3(c, k, 2 * k, 0.5L * k), "c = (%.9g %.9g %.9g)", c.x, c.y, c.z);
  scene_free(&s.scene);
}

Test(phong, eye_on_the_reflection_gives_specular_times_l_i)
{
  /* l = (-1, 1, 0)/sqrt(2), r = reflect(-l, n) = (1, 1, 0)/sqrt(2): an eye at
   * (3, 3, 0) sees r.v = 1, so any shininess gives m_spe * L_i.
   * L_i = (18, 36, 9)/18 = (1, 2, 0.5); m_spe = (0.2, 0.4, 0.6). */
  Setup s;
  Light L = point(-3, 3, 0, 18, 36, 9);
  setup(&s, (Material){.specular = vec_make(0.2f, 0.4f, 0.6f), .shininess = 50.0f}, &L, 1);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(3, 3, 0), &s.ctx);
  cr_expect(near3_rel(c, 0.2L, 0.8L, 0.3L, 50 * 4e-7L), "c = (%.9g %.9g %.9g)", c.x, c.y, c.z);
  scene_free(&s.scene);
}

Test(phong, specular_scales_with_the_incident_radiance)
{
  /* Same geometry, the light's power doubled: the highlight doubles (the
   * lecture's slide would leave it unchanged). */
  Setup s;
  Light L = point(-3, 3, 0, 36, 72, 18);
  setup(&s, (Material){.specular = vec_make(0.2f, 0.4f, 0.6f), .shininess = 50.0f}, &L, 1);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(3, 3, 0), &s.ctx);
  cr_expect(near3_rel(c, 0.4L, 1.6L, 0.6L, 50 * 4e-7L), "c = (%.9g %.9g %.9g)", c.x, c.y, c.z);
  scene_free(&s.scene);
}

Test(phong, light_behind_the_surface_gives_zero)
{
  Setup s;
  Light L[2] = {point(0, -2, 0, 100, 100, 100), point(-3, -0.001f, 0, 100, 100, 100)};
  setup(&s, (Material){.diffuse = vec_make(1, 1, 1), .specular = vec_make(1, 1, 1),
                       .shininess = 1.0f}, L, 2);
  /* The eye even sits on the reflection of the second light. */
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(3, 0.001f, 0), &s.ctx);
  cr_expect(c.x == 0.0f && c.y == 0.0f && c.z == 0.0f, "c = (%g %g %g)", c.x, c.y, c.z);
  scene_free(&s.scene);
}

Test(phong, directional_light)
{
  /* direction (0, -1, -1)/sqrt(2): l = (0, 1, 1)/sqrt(2), n.l = 1/sqrt(2);
   * c = m_dif * E / sqrt(2) with E = (1, 2, 3). */
  Setup s;
  float k = (float)(1.0L / sqrtl(2.0L));
  Light L = {.type = LIGHT_DIRECTIONAL, .direction = vec_make(0, -k, -k),
             .irradiance = vec_make(1, 2, 3)};
  setup(&s, (Material){.diffuse = vec_make(0.5f, 0.5f, 1.0f)}, &L, 1);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(0, 5, 0), &s.ctx);
  long double kl = 1.0L / sqrtl(2.0L);
  cr_expect(near3(c, 0.5L * kl, kl, 3.0L * kl), "c = (%.9g %.9g %.9g)", c.x, c.y, c.z);
  scene_free(&s.scene);
}

Test(phong, shininess_at_sixty_degrees_from_the_reflection)
{
  /* r = (1, 1, 0)/sqrt(2). v = 0.5 r + (sqrt(3)/2) z is unit with r.v = 0.5
   * (cos 60), so the lobe is 0.5^shi: 0.5, 1/256, 1 for shi 1, 8, 0.
   * L_i = 18/18 = 1, m_spe = 1, m_dif = 0.2: c = 0.2 cos45 + 0.5^shi. */
  long double k = 1.0L / sqrtl(2.0L), h = sqrtl(3.0L) / 2.0L;
  vec3s eye = vec_make((float)(4 * 0.5L * k), (float)(4 * 0.5L * k), (float)(4 * h));
  float shi[3] = {1.0f, 8.0f, 0.0f};
  long double lobe[3] = {0.5L, 1.0L / 256.0L, 1.0L};
  for (int q = 0; q < 3; q++) {
    Setup s;
    Light L = point(-3, 3, 0, 18, 18, 18);
    setup(&s, (Material){.diffuse = vec_make(0.2f, 0.2f, 0.2f), .specular = vec_make(1, 1, 1),
                         .shininess = shi[q]}, &L, 1);
    vec3s c = shade_phong(&s.scene, &s.hit, eye, &s.ctx);
    long double want = 0.2L * k + lobe[q];
    cr_expect(near3(c, want, want, want), "shininess %g: c = %.9g, expected %.9Lg", shi[q],
              c.x, want);
    scene_free(&s.scene);
  }
}

Test(phong, lights_add_up)
{
  /* The light along the normal (c = (1, 0.25, 3) alone) plus the one at 45
   * degrees with m_dif (0.5, 0.25, 1): (0.5, 0.5, 0.5)/sqrt(2). */
  Setup s;
  Light L[2] = {point(0, 2, 0, 8, 4, 12), point(-3, 3, 0, 18, 36, 9)};
  setup(&s, (Material){.diffuse = vec_make(0.5f, 0.25f, 1.0f)}, L, 2);
  vec3s c = shade_phong(&s.scene, &s.hit, vec_make(0, 5, 5), &s.ctx);
  long double k = 1.0L / sqrtl(2.0L);
  cr_expect(near3(c, 1.0L + 0.5L * k, 0.25L + 0.5L * k, 3.0L + 0.5L * k),
            "c = (%.9g %.9g %.9g)", c.x, c.y, c.z);
  scene_free(&s.scene);
}

Test(phong, trace_returns_the_background_on_a_miss)
{
  Setup s;
  Light L = point(0, 2, 0, 8, 4, 12);
  setup(&s, (Material){.diffuse = vec_make(1, 1, 1)}, &L, 1);
  s.scene.background = vec_make(0.1f, 0.2f, 0.3f);
  cr_assert(scene_prepare(&s.scene, SCENE_CAMERA | SCENE_LIGHTS));
  Ray up = {.o = vec_make(0, 1, 0), .d = vec_make(0, 1, 0)};
  vec3s c = shade_trace(&s.scene, up, &s.ctx);
  cr_expect(c.x == 0.1f && c.y == 0.2f && c.z == 0.3f);
  cr_expect(s.ctx.rays == 1, "rays counted: %llu", (unsigned long long)s.ctx.rays);
  scene_free(&s.scene);
}
