/* Phong's reflection of one light (step 04): the term PhongMaterial.Eval
 * (common/shade.h) adds for each light. docs/04-phong.md. */
#ifndef RT_PHONG_H
#define RT_PHONG_H

#include "material.h"
#include "ray.h"

/* Phong's term for one light (step 04): what the hit point, of material m,
 * sends toward the unit direction v (toward the eye) for radiance li
 * arriving from the unit direction l: li (m_dif (n.l) + m_spe
 * max(0, r.v)^shininess), r = l mirrored about n; zero when n.l <= 0. */
vec3s shade_phong_light(const Material *m, const Hit *hit, vec3s v, vec3s li, vec3s l);

#endif
