/* Light sources (step 04 on): point light (power P, L_i = P / r^2), directional
 * light (irradiance E), area light (parallelogram, step 08).
 * docs/04-phong.md, docs/08-area-lights.md. */
#ifndef RT_LIGHT_H
#define RT_LIGHT_H

#include "quad.h"

typedef enum LightType { LIGHT_POINT, LIGHT_DIRECTIONAL, LIGHT_AREA } LightType;

typedef struct Light {
  LightType type;
  vec3s power;      /* point, area: emitted power (RGB) */
  vec3s position;   /* point */
  float radius;     /* point: radius of the sphere the camera sees, 0 = none */
  vec3s direction;  /* directional: unit, where the light travels */
  vec3s irradiance; /* directional */
  Quad quad;        /* area: the emitting parallelogram */
} Light;

/* The lecture's Light.Radiance without visibility: the radiance arriving at
 * `p` from a point or directional light, the unit direction `l` from p toward
 * the light, and the distance to it (INFINITY for a directional light). A
 * point light closer to p than `min_dist` gives zero (no 1/0): the caller
 * passes the point's error bound. Not for area lights (step 08 samples them). */
vec3s light_incident(const Light *light, vec3s p, float min_dist, vec3s *l,
                     float *dist);

#endif
