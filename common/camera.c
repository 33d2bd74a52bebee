/* Pinhole camera (step 03): the lookAt basis and the lecture's GenerateRay.
 * docs/03-camera.md. */
#include "camera.h"

#include <math.h>

/* Double-precision helpers for the basis: it is computed once per render, and
 * in double it stays orthonormal to float precision even when up is within
 * 1e-7 rad of the view direction. */
typedef struct D3 {
  double x, y, z;
} D3;

static D3 d3(vec3s v) { return (D3){v.x, v.y, v.z}; }
static double d3_dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static D3 d3_cross(D3 a, D3 b)
{
  return (D3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static D3 d3_unit(D3 a)
{
  double n = sqrt(d3_dot(a, a));
  return (D3){a.x / n, a.y / n, a.z / n};
}
static vec3s d3_float(D3 a) { return vec_make((float)a.x, (float)a.y, (float)a.z); }

void camera_init(Camera *cam, vec3s eye, vec3s center, vec3s up,
                 float fov_y_deg, float focal, float aspect)
{
  cam->eye = eye;
  cam->center = center;
  cam->up = up;
  cam->fov_y_deg = fov_y_deg;
  cam->focal = focal;
  cam->aspect = aspect;
  /* BEGIN SOLUTION step 03 */
  D3 w = d3_unit((D3){(double)eye.x - center.x, (double)eye.y - center.y,
                      (double)eye.z - center.z});
  D3 u = d3_cross(d3(up), w);
  double up_len = sqrt(d3_dot(d3(up), d3(up)));
  if (!(sqrt(d3_dot(u, u)) > 1e-9 * up_len)) {
    /* up is parallel to the view direction: use the world axis least aligned
     * with w instead (the documented fallback). */
    D3 axis = fabs(w.x) < fabs(w.y) ? (fabs(w.x) < fabs(w.z) ? (D3){1, 0, 0} : (D3){0, 0, 1})
                                    : (fabs(w.y) < fabs(w.z) ? (D3){0, 1, 0} : (D3){0, 0, 1});
    u = d3_cross(axis, w);
  }
  u = d3_unit(u);
  D3 v = d3_cross(w, u);
  cam->u = d3_float(u);
  cam->v = d3_float(v);
  cam->w = d3_float(w);
  /* Inverse of the view matrix: columns u, v, w and the eye (glms_lookat's
   * rotation transposed; the inverse of an orthonormal basis is exact). */
  mat4s m = glms_mat4_identity();
  m.col[0] = glms_vec4(cam->u, 0.0f);
  m.col[1] = glms_vec4(cam->v, 0.0f);
  m.col[2] = glms_vec4(cam->w, 0.0f);
  m.col[3] = glms_vec4(eye, 1.0f);
  cam->cam_to_world = m;
  cam->half_h = focal * tanf(0.5f * glm_rad(fov_y_deg));
  cam->half_w = cam->half_h * aspect;
  /* END SOLUTION */
}

Ray camera_ray(const Camera *cam, float nx, float ny)
{
  /* BEGIN SOLUTION step 03 */
  /* The point on the image plane z = -f in camera space. The lecture takes
   * t = V^-1 p and o = V^-1 (0,0,0,1) and normalizes t - o; that difference is
   * V^-1 applied to p as a direction (w = 0), computed here directly, so a far
   * eye (|eye| = 1e5) does not cancel away the direction's low bits. */
  vec3s p_cam = vec_make(-cam->half_w + 2.0f * cam->half_w * nx,
                         -cam->half_h + 2.0f * cam->half_h * ny, -cam->focal);
  vec3s d_world = glms_mat4_mulv3(cam->cam_to_world, p_cam, 0.0f);
  Ray r = {.o = cam->eye, .d = glms_vec3_normalize(d_world)};
  return r;
  /* STUB: return (Ray){.o = cam->eye, .d = vec_make(0.0f, 0.0f, -1.0f)}; */
  /* END SOLUTION */
}
