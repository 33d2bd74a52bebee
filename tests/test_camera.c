/* Unit tests of the camera (step 03): the lookAt basis and the lecture's
 * GenerateRay, against closed forms and cglm's lookAt. docs/03-camera.md. */
#include "check.h"

#include "camera.h"

#define DOC "docs/03-camera.md, \"What you write\""

/* A float basis is a few roundings off the exact one: 4e-7 per component
 * (about 4 ulps of values near 0.5 .. 1). A ray direction may also carry the
 * rounding of the eye's coordinates (the lecture's normalize(t - o) form), a
 * few ulps of |eye| = 3: 1e-6. */
static const double BASIS_TOL = 4e-7, DIR_TOL = 1e-6;

/* Unit vector of (x, y, z) in long double. */
static void unit_l(long double v[3])
{
  long double n = sqrtl(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; k++)
    v[k] /= n;
}

static vec3s to_float(const long double v[3])
{
  return vec_make((float)v[0], (float)v[1], (float)v[2]);
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
  Check ck = CHECK("camera_init", DOC);
  const char *cam = "eye (1, 2, 3), center (4, -1, 7), up (0, 1, 0)";
  CHECK_VEC(&ck, to_float(w), c.w, BASIS_TOL, "%s: w = normalize(eye - center)", cam);
  CHECK_VEC(&ck, to_float(u), c.u, BASIS_TOL, "%s: u = normalize(up x w)", cam);
  CHECK_VEC(&ck, to_float(v), c.v, BASIS_TOL, "%s: v = w x u", cam);
}

Test(camera, basis_is_orthonormal_even_when_up_is_nearly_the_view)
{
  /* The third up is 1e-4 off the (reversed) view direction: up x w is then
   * 2e-5 long, and a float cross product loses most of its bits (the doc's
   * remedy: the basis in double). */
  vec3s ups[3] = {UP, vec_make(0.3f, 0.9f, -0.2f), vec_make(3.0f, -3.0f + 1e-4f, 4.0f)};
  const char *what[3] = {"up (0, 1, 0)", "up (0.3, 0.9, -0.2)",
                         "up (3, -3 + 1e-4, 4), 1e-4 off the view direction"};
  static const char axis[3] = {'u', 'v', 'w'};
  Check ck = CHECK("camera_init", DOC);
  for (int k = 0; k < 3; k++) {
    Camera c;
    camera_init(&c, EYE, CENTER, ups[k], 45.0f, 1.0f, 1.0f);
    vec3s b[3] = {c.u, c.v, c.w};
    for (int i = 0; i < 3; i++)
      for (int j = i; j < 3; j++)
        CHECK_NEAR(&ck, i == j ? 1.0 : 0.0, glms_vec3_dot(b[i], b[j]), BASIS_TOL,
                   "eye (1, 2, 3), center (4, -1, 7), %s: %c.%c", what[k], axis[i], axis[j]);
    /* Right-handed: u x v = w. */
    CHECK_NEAR(&ck, 1.0, glms_vec3_dot(glms_vec3_cross(c.u, c.v), c.w), 1e-6,
               "%s: (u x v).w (right-handed: u x v = w)", what[k]);
  }
  CHECK_DONE(&ck);
}

Test(camera, centre_ray_points_at_center)
{
  Camera c;
  camera_init(&c, EYE, CENTER, UP, 60.0f, 1.0f, 2.0f);
  Ray r = camera_ray(&c, 0.5f, 0.5f);
  long double want[3] = {3, -3, 4};
  unit_l(want);
  Check ck = CHECK("camera_ray", DOC);
  /* The lecture's o = V^-1 (0, 0, 0, 1) rounds: a few ulps of |eye| are free. */
  CHECK_VEC(&ck, EYE, r.o, 4.0 * 0x1p-24 * 3.0, "film centre (0.5, 0.5): the ray starts at "
            "the eye (1, 2, 3)");
  CHECK_VEC(&ck, to_float(want), r.d, DIR_TOL, "film centre (0.5, 0.5), eye (1, 2, 3), "
            "center (4, -1, 7): d points at the center");
  CHECK_NEAR(&ck, 1.0, glms_vec3_norm(r.d), 4e-7, "film centre: |d| (d must be unit)");
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
  Check ck = CHECK("camera_ray", DOC);
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    Ray r = camera_ray(&c, cases[k].nx, cases[k].ny);
    CHECK_NEAR(&ck, (double)cases[k].angle, (double)angle(r.d, view), DIR_TOL,
               "fov 60, aspect 2, film point (%g, %g): angle of d to the view direction "
               "(radians)", cases[k].nx, cases[k].ny);
    /* Top of the film goes along +v, its right along +u. */
    float up = glms_vec3_dot(r.d, c.v), right = glms_vec3_dot(r.d, c.u);
    const char *up_want = cases[k].up_sign > 0 ? "> 0.1" : cases[k].up_sign < 0 ? "< -0.1" : "0";
    const char *right_want = cases[k].right_sign > 0 ? "> 0.1"
                             : cases[k].right_sign < 0 ? "< -0.1" : "0";
    CHECK_THAT(&ck, cases[k].up_sign == 0 ? fabsf(up) < 1e-6f : up * cases[k].up_sign > 0.1f,
               "film point (%g, %g): d.v (the top of the film is along +v)\n"
               "  expected %s\n  got      %.9g", cases[k].nx, cases[k].ny, up_want, up);
    CHECK_THAT(&ck, cases[k].right_sign == 0 ? fabsf(right) < 1e-6f
                                             : right * cases[k].right_sign > 0.1f,
               "film point (%g, %g): d.u (the right of the film is along +u)\n"
               "  expected %s\n  got      %.9g", cases[k].nx, cases[k].ny, right_want, right);
  }
  CHECK_DONE(&ck);
}

Test(camera, cam_to_world_is_the_inverse_of_cglm_lookat)
{
  vec3s eyes[2] = {EYE, vec_make(-5.0f, 0.5f, 0.0f)};
  vec3s centers[2] = {CENTER, vec_make(0.0f, 0.0f, 0.0f)};
  Check ck = CHECK("camera_init", DOC);
  for (int k = 0; k < 2; k++) {
    Camera c;
    camera_init(&c, eyes[k], centers[k], UP, 40.0f, 1.0f, 1.5f);
    mat4s inv = glms_mat4_inv(glms_lookat(eyes[k], centers[k], UP));
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
        CHECK_NEAR(&ck, inv.col[i].raw[j], c.cam_to_world.col[i].raw[j], 1e-5,
                   "camera %d (eye (%g, %g, %g)): cam_to_world column %d, row %d against "
                   "cglm's glms_mat4_inv(glms_lookat(...))", k, eyes[k].x, eyes[k].y,
                   eyes[k].z, i, j);
  }
  CHECK_DONE(&ck);
}

Test(camera, default_looks_down_minus_z)
{
  Camera c;
  camera_init(&c, vec_make(0, 0, 0), vec_make(0, 0, -1), UP, 90.0f, 1.0f, 1.0f);
  /* fov 90, square: the right-middle ray is (1, 0, -1)/sqrt(2). */
  Ray r = camera_ray(&c, 1.0f, 0.5f);
  long double want[3] = {1, 0, -1};
  unit_l(want);
  Check ck = CHECK("camera_ray", DOC);
  CHECK_VEC(&ck, to_float(want), r.d, BASIS_TOL, "eye at the origin looking down -z, fov 90, "
            "square film, right middle (1, 0.5): d");
  CHECK_VEC(&ck, vec_make(0, 0, -1), camera_ray(&c, 0.5f, 0.5f).d, BASIS_TOL,
            "the same camera, film centre (0.5, 0.5): d");
}
