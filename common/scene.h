/* Scene: camera, film size, materials, lights and the instances that pair a
 * shape with a material or a light (the lecture's object instances), with the
 * closest-hit and any-hit queries. Introduced in step 02; docs/02-intersection.md
 * and docs/05-shadows.md (any-hit). */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stdbool.h>
#include "camera.h"
#include "light.h"
#include "material.h"
#include "sampler.h"
#include "shapes.h"

/* The kinds of shape an instance may be, one per line of SHAPE_REGISTRY
 * (common/shapes.h): SHAPE_SPHERE, SHAPE_PLANE, SHAPE_QUAD, SHAPE_DISC, ...
 * docs/extending.md lists what a new one takes. */
#define SHAPE_ENUM_(NAME, name, Type, STORE, DOC) SHAPE_##NAME,
typedef enum ShapeType { SHAPE_REGISTRY(SHAPE_ENUM_) SHAPE_COUNT } ShapeType;
#undef SHAPE_ENUM_

/* A shape paired with a material or a light. The instance holds its shape
 * (INPLACE in SHAPE_REGISTRY), except an area light's quad, which it points
 * to (KEPT: Scene.lights[light].quad). The member is named as the shape. */
#define SHAPE_MEMBER_(NAME, name, Type, STORE, DOC) SHAPE_MEMBER_##STORE(Type, name)
typedef struct Instance {
  ShapeType shape;
  int material;         /* index into Scene.materials, or -1 for a light's shape */
  int light;            /* index into Scene.lights, or -1 for a lit object */
  union {
    SHAPE_REGISTRY(SHAPE_MEMBER_)
  };
} Instance;
#undef SHAPE_MEMBER_

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

struct Scene;

/* The scene's two queries as a table of functions, which scene_intersect and
 * scene_occluded call when Scene.index points to one: an index over the
 * instances (the speed pack's, app/pack.h), or a wrapper that records or
 * counts the queries and passes them on. It only chooses which instances a
 * query tests; every test calls the shape's own function
 * (scene_instance_hit_t), so its answers are the plain loop's: the closest
 * hit keeps the first of equal distances in instance order, as the loop
 * does. Whoever fills the table owns it and what it stands for. */
typedef struct SceneIndex {
  /* Closest instance with t in (0, *tmax), *tmax becoming its distance; NULL
   * when none. The ray by address: a Ray passed by value goes through the
   * stack, and the caller then rebuilt it there piecewise and read it back
   * whole, a stalled load per camera ray (docs/performance.md). */
  const struct Instance *(*closest)(const struct Scene *scene, const Ray *r, float *tmax);
  /* True when some lit shape lies on the ray with t in (0, tmax). */
  bool (*any)(const struct Scene *scene, const Ray *r, float tmax);
} SceneIndex;

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
  Instance *instances;     /* lit shapes first, then the lights' shapes */
  int n_instances;         /* all instances the camera sees */
  int n_shapes;            /* instances [0, n_shapes) have a material */
  SceneInfo info;          /* set by scene_prepare */
  const SceneIndex *index; /* the queries' table, not owned; NULL: they test
                            * every instance in order */
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
bool scene_add_instance(Scene *scene, const Instance *inst);

/* The box of an instance's shape (sphere_bounds, plane_bounds, ...):
 * infinite along the axes an unbounded shape extends in (box_is_bounded). */
Box scene_instance_bounds(const Instance *inst);

/* The shape's name, as the statement that makes it is written ("sphere");
 * a quad is an area light's. */
const char *scene_shape_name(ShapeType shape);

/* Get the scene ready for a step that handles `features` (SceneFeature bits):
 * drop what it cannot render (recorded in info.ignored), order the instances,
 * fill info and derive the camera for the film's aspect. The lights' shapes
 * point into Scene.lights: a light added afterwards needs another call. Sets
 * Scene.index to NULL: an index is built afterwards, by whoever wants one
 * (pack_index, app/pack.h).
 * False when out of memory (the scene is then only fit for scene_free). */
bool scene_prepare(Scene *scene, unsigned features);

/* Distance to one instance along the ray with t in (0, tmax), INFINITY when
 * missed: its shape's name_hit_t (the student's sphere_hit_t, plane_hit_t;
 * the given quad_hit_t, disc_hit_t, ...). */
float scene_instance_hit_t(const Instance *inst, Ray r, float tmax);

/* The query table's answers (scene->index's, or without one every instance
 * tested in order): the closest instance with t in (0, *tmax), *tmax becoming
 * its distance, NULL when none; whether some lit shape lies on the ray with t
 * in (0, tmax). What scene_intersect and scene_occluded ask; a wrapper around
 * the table (the render's counting, --trace's recording) answers with them. */
const Instance *scene_closest(const Scene *scene, const Ray *r, float *tmax);
bool scene_any(const Scene *scene, const Ray *r, float tmax);

/* Closest hit with t in (0, tmax) among all instances (lit shapes and lights'
 * shapes). False when the ray hits nothing. */
bool scene_intersect(const Scene *scene, Ray r, float tmax, Hit *hit);

/* Any-hit query: true when some lit shape (lights' shapes never occlude) lies
 * on the ray with t in (0, tmax). Stops at the first one found. */
bool scene_occluded(const Scene *scene, Ray r, float tmax);

/* The index of the material called `name`, or -1. */
int scene_find_material(const Scene *scene, const char *name);

#endif
