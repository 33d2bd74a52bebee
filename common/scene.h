/* Scene: camera, film size, materials, lights and the instances that pair a
 * shape with a material or a light (the lecture's object instances), with the
 * closest-hit and any-hit queries. Introduced in step 02; docs/02-intersection.md
 * and docs/05-shadows.md (any-hit). The table the queries go through, for
 * whoever builds or wraps one: scene_index.h. */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stdbool.h>
#include "camera.h"
#include "light.h"
#include "material.h"
#include "sampler.h"

/* What a step knows how to render; the rest of a scene is ignored (and said). */
enum SceneFeature {
  SCENE_CAMERA = 1u << 0,         /* the lookAt camera (step 03) */
  SCENE_LIGHTS = 1u << 1,         /* point and directional lights (step 04) */
  SCENE_AMBIENT = 1u << 2,        /* ambient light (step 06) */
  SCENE_LIGHT_SHAPES = 1u << 3,   /* lights the camera sees (step 06) */
  SCENE_SAMPLES = 1u << 4,        /* several samples per pixel (step 07) */
  SCENE_AREA_LIGHTS = 1u << 5,    /* area lights and light_samples (step 08) */
  SCENE_SHADOWS = 1u << 6,        /* shadows (step 05): without it, the
                                   * shading traces no shadow ray */
};

/* What scene_prepare found the scene needs, so renderers skip the rest. */
typedef struct SceneInfo {
  bool ambient;        /* ambient light times some ambient colour is non-zero */
  bool shadows;        /* the step casts shadows (SCENE_SHADOWS) */
  unsigned ignored;    /* SceneFeature bits present in the scene but not rendered */
} SceneInfo;

typedef struct Scene {
  int width, height;       /* film size in pixels (default 800 x 600) */
  Camera camera;           /* default: eye 0 0 0, center 0 0 -1, up 0 1 0, fov 45 */
  vec3s ambient;           /* ambient light l_amb (default 0) */
  vec3s background;        /* colour of rays that hit nothing (default 0) */
  int samples;             /* camera samples per pixel (default 1) */
  int light_samples;       /* samples per area light (default 1) */
  Sampler sampler;         /* where the samples go (default: centre, seed 1,
                            * not adaptive) */
  Material *materials;
  int n_materials;
  Light *lights;
  int n_lights;
  struct Instance *instances; /* lit shapes first, then the lights' shapes
                               * (common/shapes.h) */
  int n_instances;         /* all instances the camera sees */
  int n_shapes;            /* instances [0, n_shapes) have a material */
  SceneInfo info;          /* set by scene_prepare */
  const struct SceneIndex *index; /* the queries' table (scene_index.h), not
                                   * owned; NULL: they test every instance in
                                   * order */
} Scene;

/* Scene limits the parser enforces (no memory blow-up from one line). */
enum { SCENE_MAX_SAMPLES = 65536 };

/* An empty scene with the defaults above. */
void scene_init(Scene *scene);

/* Free everything the scene owns; a second call is harmless. */
void scene_free(Scene *scene);

/* Append a material, light or instance (copied). False when out of memory. */
bool scene_add_material(Scene *scene, const Material *m);
bool scene_add_light(Scene *scene, const Light *light);
bool scene_add_instance(Scene *scene, const struct Instance *inst);

/* Get the scene ready for a step that handles `features` (SceneFeature bits):
 * drop what it cannot render (recorded in info.ignored), order the instances,
 * fill info and derive the camera for the film's aspect. The lights' shapes
 * point into Scene.lights: a light added afterwards needs another call. Sets
 * Scene.index to NULL: an index is built afterwards, by whoever wants one
 * (pack_index, app/pack.h).
 * False when out of memory (the scene is then only fit for scene_free). */
bool scene_prepare(Scene *scene, unsigned features);

/* Closest hit with t in (0, tmax) among all instances (lit shapes and lights'
 * shapes). False when the ray hits nothing. */
bool scene_intersect(const Scene *scene, Ray r, float tmax, Hit *hit);

/* Any-hit query: true when some lit shape (lights' shapes never occlude) lies
 * on the ray with t in (0, tmax). Stops at the first one found. */
bool scene_occluded(const Scene *scene, Ray r, float tmax);

/* The index of the material called `name`, or -1. */
int scene_find_material(const Scene *scene, const char *name);

#endif
