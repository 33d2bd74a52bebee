/* Unit tests of the camera (step 03): the lookAt basis and the lecture's
 * GenerateRay, against closed forms and cglm's lookAt. docs/03-camera.md. */
#include <criterion/criterion.h>

#include <math.h>

#include "camera.h"

/* Unit vector of (x, y, z) in long double. */
static void unit_l(long double v[3])
{
  long double n = sqrtl(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; k++)
    v[k] /= n;
}

static void expect_vec(vec3s got, const long double want[3], long double tol, const char *what)
{
  for (int k = 0; k < 3; k++)
    cr_expect(fabsl(got.raw[k] - want[k]) <= tol, "%s[%d] = %.9g, expected %.9Lg", what, k,
              got.raw[k], want[k]);
}

/* Angle between two vectors, long double. */
static long double angle(vec3s a, const long double b[3])
{
  long double d = a.x * b[0] + a.y * b[1] + a.z * b[2];
  long double na = sqrtl((long double)a.x * a.x + (long double)a.y * a.y + (long double)a.z * a.z);
  long double nb = sqrtl(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  return acosl(fminl(1.0L, d / (na * nb)));
}

static const vec3s EYE = {.x = 1.0f, .y = 2.0f, .z = 3.0f};
static const vec3s CENTER = {.x = 4.0f, .y = -1.0f, .z = 7.0f};
static const vec3s UP = {.x = 0.0f, .y = 1.0f, .z = 0.0f};

Test(camera, basis_is_the_lookat_basis)
{
  Camera c;
  camera_init(&c, EYE, CENTER, UP, 60.0f, 1.0f, 2.0f);
  /* w = normalize(eye - center) = (-3, 3, -4)/sqrt(34);
   * u = normalize(up x w): (0,1,0) x (-3,3,-4) = (1*(-4) - 0*3, 0*(-3) - 0*(-4), 0*3 - 1*(-3))
   *   = (-4, 0, 3), / 5; v = w x u. */
  long double w[3] = {-3, 3, -4}, u[3] = {-4, 0, 3};
  unit_l(w);
  unit_l(u);
  long double v[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2],
                      w[0] * u[1] - w[1] * u[0]};
  expect_vec(c.w, w, 1e-7L, "w");
  expect_vec(c.u, u, 1e-7L, "u");
  expect_vec(c.v, v, 1e-7L, "v");
  cr_expect(v[1] > 0.0L, "v points up");
}

Test(camera, basis_is_orthonormal_even_when_up_is_nearly_the_view)
{
  vec3s ups[3] = {UP, vec_make(0.3f, 0.9f, -0.2f), vec_make(3.0f, -3.0f + 1e-4f, 4.0f)};
  for (int k = 0; k < 3; k++) {
    Camera c;
    camera_init(&c, EYE, CENTER, ups[k], 45.0f, 1.0f, 1.0f);
    vec3s b[3] = {c.u, c.v, c.w};
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        float d = glms_vec3_dot(b[i], b[j]);
        cr_expect(fabsf(d - (i == j ? 1.0f : 0.0f)) < 2e-7f, "up %d: b%d.b%d = %.9g", k, i, j, d);
      }
    /* Right-handed: u x v = w. */
    vec3s x = glms_vec3_cross(c.u, c.v);
    cr_expect(glms_vec3_dot(x, c.w) > 1.0f - 1e-6f, "up %d: u x v != w", k);
  }
}

Test(camera, centre_ray_points_at_center)
{
  Camera c;
  camera_init(&c, EYE, CENTER, UP, 60.0f, 1.0f, 2.0f);
  Ray r = camera_ray(&c, 0.5f, 0.5f);
  long double want[3] = {3, -3, 4};
  unit_l(want);
  cr_expect(r.o.x == EYE.x && r.o.y == EYE.y && r.o.z == EYE.z, "ray starts at the eye");
  expect_vec(r.d, want, 2e-7L, "d");
  cr_expect(fabsf(glms_vec3_norm(r.d) - 1.0f) < 2e-7f, "d is unit");
}

Test(camera, edge_and_corner_rays_make_the_field_of_view)
{
  /* fov 60, aspect 2, focal 3 (focal must not matter): half height
   * tan(30) = 1/sqrt(3), half width 2/sqrt(3). The ray through the top
   * middle is 30 degrees off the view direction, the right middle
   * atan(2/sqrt(3)), a corner atan(sqrt(4/3 + 1/3)). */
  Camera c;
  camera_init(&c, EYE, CENTER, UP, 60.0f, 3.0f, 2.0f);
  long double view[3] = {3, -3, 4};
  unit_l(view);
  long double half_h = 1.0L / sqrtl(3.0L), half_w = 2.0L * half_h;
  long double pi = acosl(-1.0L);
  struct {
    float nx, ny;
    long double angle;
    float up_sign, right_sign;
  } cases[] = {
      {0.5f, 1.0f, pi / 6.0L, 1, 0},
      {0.5f, 0.0f, pi / 6.0L, -1, 0},
      {1.0f, 0.5f, atanl(half_w), 0, 1},
      {0.0f, 0.5f, atanl(half_w), 0, -1},
      {0.0f, 0.0f, atanl(sqrtl(half_w * half_w + half_h * half_h)), -1, -1},
      {1.0f, 1.0f, atanl(sqrtl(half_w * half_w + half_h * half_h)), 1, 1},
      {0.0f, 1.0f, atanl(sqrtl(half_w * half_w + half_h * half_h)), 1, -1},
      {1.0f, 0.0f, atanl(sqrtl(half_w * half_w + half_h * half_h)), -1, 1},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    Ray r = camera_ray(&c, cases[k].nx, cases[k].ny);
    long double a = angle(r.d, view);
    cr_expect(fabsl(a - cases[k].angle) < 1e-6L, "(%g, %g): %.9Lg rad, expected %.9Lg",
              cases[k].nx, cases[k].ny, a, cases[k].angle);
    /* Top of the film goes along +v, its right along +u. */
    float up = glms_vec3_dot(r.d, c.v), right = glms_vec3_dot(r.d, c.u);
    cr_expect(cases[k].up_sign == 0 ? fabsf(up) < 1e-6f : up * cases[k].up_sign > 0.1f,
              "(%g, %g): d.v = %g", cases[k].nx, cases[k].ny, up);
    cr_expect(cases[k].right_sign == 0 ? fabsf(right) < 1e-6f : right * cases[k].right_sign > 0.1f,
              "(%g, %g): d.u = %g", cases[k].nx, cases[k].ny, right);
  }
}

Test(camera, cam_to_world_is_the_inverse_of_cglm_lookat)
{
  vec3s eyes[2] = {EYE, vec_make(-5.0f, 0.5f, 0.0f)};
  vec3s centers[2] = {CENTER, vec_make(0.0f, 0.0f, 0.0f)};
  for (int k = 0; k < 2; k++) {
    Camera c;
    camera_init(&c, eyes[k], centers[k], UP, 40.0f, 1.0f, 1.5f);
    mat4s inv = glms_mat4_inv(glms_lookat(eyes[k], centers[k], UP));
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
        cr_expect(fabsf(c.cam_to_world.col[i].raw[j] - inv.col[i].raw[j]) < 1e-5f,
                  "camera %d: [%d][%d] = %.9g, cglm %.9g", k, i, j,
                  c.cam_to_world.col[i].raw[j], inv.col[i].raw[j]);
  }
}

Test(camera, default_looks_down_minus_z)
{
  Camera c;
  camera_init(&c, vec_make(0, 0, 0), vec_make(0, 0, -1), UP, 90.0f, 1.0f, 1.0f);
  /* fov 90, square: the right-middle ray is (1, 0, -1)/sqrt(2). */
  Ray r = camera_ray(&c, 1.0f, 0.5f);
  long double want[3] = {1, 0, -1};
  unit_l(want);
  expect_vec(r.d, want, 2e-7L, "d");
  r = camera_ray(&c, 0.5f, 0.5f);
  cr_expect(r.d.x == 0.0f && r.d.y == 0.0f && r.d.z == -1.0f);
}
