/* Scenes for step 05's shadow tests (tests/test_shadows.c and
 * tests/test_shadows_lecture.c): one white material, spheres, planes, point
 * and directional lights. docs/05-shadows.md, "What you write". */
#ifndef RT_SHADOW_SCENE_H
#define RT_SHADOW_SCENE_H

#include "check.h"
#include "counting.h"
#include "scene.h"
#include "shade.h"
#include "shapes.h"

#define DOC "docs/05-shadows.md, \"What you write\""
#define SPAWN_DOC "docs/05-shadows.md, \"Self-intersection: where the shadow ray starts\""
/* What a shadow test runs besides the step's own functions. */
#define RELIES "light_incident (step 04), sphere_hit_t, plane_hit_t (step 02)"

static inline Check shadow_check(void)
{
  return CHECK_RELYING("shade_visible, ray_spawn", DOC, RELIES);
}

/* A scene with one white diffuse material (index 0). */
static inline void scene_start(Scene *s)
{
  scene_init(s);
  Material m = {.name = "white", .ambient = vec_make(0.5f, 0.5f, 0.5f),
                .diffuse = vec_make(0.5f, 0.5f, 0.5f)};
  cr_assert(scene_add_material(s, &m), "out of memory");
}

static inline void add_sphere(Scene *s, vec3s c, float r)
{
  Instance in = {.shape = SHAPE_SPHERE, .sphere = {.center = c, .radius = r},
                 .material = 0, .light = -1};
  cr_assert(scene_add_instance(s, &in), "out of memory");
}

static inline void add_plane(Scene *s, vec3s point, vec3s normal)
{
  Plane pl = plane_make(point, normal);
  Instance in = {.shape = SHAPE_PLANE, .plane = pl, .material = 0,
                 .light = -1};
  cr_assert(scene_add_instance(s, &in), "out of memory");
}

static inline void add_point(Scene *s, vec3s pos, vec3s power)
{
  Light l = {.type = LIGHT_POINT, .position = pos, .power = power};
  cr_assert(scene_add_light(s, &l), "out of memory");
}

static inline void add_directional(Scene *s, vec3s dir, vec3s irradiance)
{
  Light l = {.type = LIGHT_DIRECTIONAL, .direction = glms_vec3_normalize(dir),
             .irradiance = irradiance};
  cr_assert(scene_add_light(s, &l), "out of memory");
}

static inline void prepare(Scene *s)
{
  cr_assert(scene_prepare(s, SCENE_CAMERA | SCENE_LIGHTS | SCENE_SHADOWS), "out of memory");
}

#endif
