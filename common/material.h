/* Phong material (step 04): ambient, diffuse and specular colours and the
 * shininess exponent. docs/04-phong.md. */
#ifndef RT_MATERIAL_H
#define RT_MATERIAL_H

#include "vec.h"

enum { MATERIAL_NAME_MAX = 64 };

typedef struct Material {
  char name[MATERIAL_NAME_MAX];
  vec3s ambient;   /* defaults to diffuse */
  vec3s diffuse;
  vec3s specular;
  float shininess; /* exponent of max(0, r.v) */
} Material;

#endif
