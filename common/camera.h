/* Pinhole camera: lookAt basis and the lecture's GenerateRay (step 03).
 * Rays are made in camera space, then taken to world space by the inverse of
 * the view matrix. docs/03-camera.md. */
#ifndef RT_CAMERA_H
#define RT_CAMERA_H

#include "ray.h"

typedef struct Camera {
  vec3s eye, center, up; /* extrinsic parameters, world space */
  float fov_y_deg;       /* vertical field of view, (0, 180) */
  float focal;           /* distance of the image plane, > 0 */
  float aspect;          /* film width / height */
  vec3s u, v, w;         /* orthonormal basis, w = normalize(eye - center) */
  mat4s cam_to_world;    /* inverse of the view matrix: [u v w eye] */
  float half_h, half_w;  /* image plane half extents: f tan(fov/2), * aspect */
} Camera;

/* Set the camera and derive its basis. When `up` is parallel (or almost) to the
 * view direction, the basis still comes out orthonormal: u is then taken
 * perpendicular to the world axis least aligned with w (docs/03-camera.md).
 * eye must differ from center; the scene parser rejects the other cases. */
void camera_init(Camera *cam, vec3s eye, vec3s center, vec3s up,
                 float fov_y_deg, float focal, float aspect);

/* The lecture's GenerateRay: the world-space ray through normalized film
 * coordinates (nx, ny) in [0,1]^2, (0,0) the bottom-left corner. */
Ray camera_ray(const Camera *cam, float nx, float ny);

#endif
