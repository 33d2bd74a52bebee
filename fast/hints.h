/* The speed pack's compiler hints for common/shade.c, which the build
 * includes ahead of that file (-include, Makefile) where FAST=1, so the
 * student's file holds none of them. A hint changes how the compiler lays
 * out the code, never what it computes: the pictures are the same bytes
 * with or without it (bench/same-pictures.sh). docs/performance.md, "Build
 * flags". */
#ifndef RT_FAST_HINTS_H
#define RT_FAST_HINTS_H

#include "shade.h"

/* flatten: every shading function shade_sample calls is compiled into it,
 * one body per camera sample (gcc and clang take the attribute from this
 * earlier declaration; with gcc's link-time optimisation, from phong.c,
 * shadow.c and area_light.c too). Without it the compiler keeps
 * shade_visible, shade_incident and scene_intersect as calls, since the
 * tracer and step 08's shade_area call them too. */
__attribute__((flatten)) vec3s shade_sample(const Scene *scene, float x, float y);

#endif
