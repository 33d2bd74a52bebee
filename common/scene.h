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
#include "shapes.h"

/* The kinds of shape an instance may be, one per line of SHAPE_REGISTRY
 * (common/shapes.h): SHAPE_SPHERE, SHAPE_PLANE, SHAPE_QUAD, SHAPE_DISC, ...
 * docs/extending.md lists what a new one takes. */
#define SHAPE_ENUM_(NAME, name, Type, STORE, DOC) SHAPE_##NAME,
typedef enum ShapeType { SHAPE_REGISTRY(SHAPE_ENUM_) SHAPE_COUNT } ShapeType;
#undef SHAPE_ENUM_

/* A shape paired with a material or a light. A small shape is kept in place
 * (the sphere: `Sphere sphere`); a larger one where the scene keeps it
 * (`const Plane *plane`: the scene's copy, scene_keep; a quad's is its area
 * light's, Scene.lights[light].quad), so that every instance stays as small
 * as a sphere's. The member is named as the shape (SHAPE_REGISTRY's STORE column). */
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

/* A shape kept in place fits where a sphere does. */
#define SHAPE_SMALL_(NAME, name, Type, STORE, DOC)                                    \
  _Static_assert(SHAPE_FITS_##STORE(Type), #name " is kept in place (INPLACE in "     \
                 "common/shapes.h): at most 16 bytes, else KEPT");
#define SHAPE_FITS_INPLACE(Type) sizeof(Type) <= 16
#define SHAPE_FITS_KEPT(Type) 1
SHAPE_REGISTRY(SHAPE_SMALL_)
#undef SHAPE_SMALL_

/* What a step knows how to render; the rest of a scene is ignored (and said). */
enum SceneFeature {
  SCENE_CAMERA = 1u << 0,         /* the lookAt camera (step 03) */
  SCENE_LIGHTS = 1u << 1,         /* point and directional lights (step 04) */
  SCENE_AMBIENT = 1u << 2,        /* ambient light (step 06) */
  SCENE_LIGHT_SHAPES = 1u << 3,   /* lights the camera sees (step 06) */
  SCENE_SAMPLES = 1u << 4,        /* several samples per pixel (step 07) */
  SCENE_AREA_LIGHTS = 1u << 5,    /* area lights and light_samples (step 08) */
};

/* What scene_prepare found the scene needs, so renderers skip the rest. */
typedef struct SceneInfo {
  bool ambient;        /* ambient light times some ambient colour is non-zero */
  unsigned ignored;    /* SceneFeature bits present in the scene but not rendered */
} SceneInfo;

struct Scene;

/* An acceleration structure over the instances (pack_index, app/pack.h,
 * builds one). It only chooses which instances a query tests; every test calls the
 * shape's own function (scene_instance_hit_t), so its answers are the plain
 * loop's: the closest hit keeps the first of equal distances in instance
 * order, as the loop does. */
typedef struct SceneIndex {
  /* Closest instance with t in (0, *tmax), *tmax becoming its distance; NULL
   * when none. The ray by address: a Ray passed by value goes through the
   * stack, and the caller then rebuilt it there piecewise and read it back
   * whole, a stalled load per camera ray (docs/performance.md). */
  const struct Instance *(*closest)(const struct Scene *scene, const Ray *r, float *tmax);
  /* True when some lit shape lies on the ray with t in (0, tmax). */
  bool (*any)(const struct Scene *scene, const Ray *r, float tmax);
  void (*destroy)(struct SceneIndex *index); /* frees the index */
} SceneIndex;

typedef struct Scene {
  int width, height;       /* film size in pixels (default 800 x 600) */
  Camera camera;           /* default: eye 0 0 0, center 0 0 -1, up 0 1 0, fov 45 */
  vec3s ambient;           /* ambient light l_amb (default 0) */
  vec3s background;        /* colour of rays that hit nothing (default 0) */
  int samples;             /* camera samples per pixel (default 1) */
  int light_samples;       /* samples per area light (default 1) */
  Material *materials;
  int n_materials;
  Light *lights;
  int n_lights;
  void **kept;             /* the shapes instances point to (scene_keep),
                            * each owned */
  int n_kept;
  Instance *instances;     /* lit shapes first, then the lights' shapes */
  int n_instances;         /* all instances the camera sees */
  int n_shapes;            /* instances [0, n_shapes) have a material */
  SceneInfo info;          /* set by scene_prepare */
  SceneIndex *index;       /* acceleration structure, owned; NULL: the queries
                            * test every instance in order */
  bool no_occluders;       /* scene_occluded answers false: a view of the
                            * scene (scene_view_unoccluded) for points that
                            * nothing can shadow */
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

/* scene_keep for a plane (a SHAPE_PLANE instance's). */
const Plane *scene_add_plane(Scene *scene, const Plane *plane);

/* A copy of the `size` bytes of `shape` (a Plane, a Disc, ...), kept by the
 * scene until scene_free, for an instance to point to; NULL when out of
 * memory (one line printed). */
const void *scene_keep(Scene *scene, const void *shape, size_t size);

/* The box of an instance's shape (sphere_bounds, plane_bounds, ...):
 * infinite along the axes an unbounded shape extends in (box_is_bounded). */
Box scene_instance_bounds(const Instance *inst);

/* The shape's name, as the statement that makes it is written ("sphere");
 * a quad is an area light's. */
const char *scene_shape_name(ShapeType shape);

/* Get the scene ready for a step that handles `features` (SceneFeature bits):
 * drop what it cannot render (recorded in info.ignored), order the instances,
 * fill info and derive the camera for the film's aspect. The lights' shapes
 * point into Scene.lights: a light added afterwards needs another call. The acceleration
 * structure is built afterwards, by whoever wants one (accel_build).
 * False when out of memory (the scene is then only fit for scene_free). */
bool scene_prepare(Scene *scene, unsigned features);

/* Distance to one instance along the ray with t in (0, tmax), INFINITY when
 * missed: its shape's name_hit_t (the student's sphere_hit_t, plane_hit_t;
 * the given quad_hit_t, disc_hit_t, ...). */
float scene_instance_hit_t(const Instance *inst, Ray r, float tmax);

/* Closest hit with t in (0, tmax) among all instances (lit shapes and lights'
 * shapes). False when the ray hits nothing. */
bool scene_intersect(const Scene *scene, Ray r, float tmax, Hit *hit);

/* Any-hit query: true when some lit shape (lights' shapes never occlude) lies
 * on the ray with t in (0, tmax). Stops at the first one found. */
bool scene_occluded(const Scene *scene, Ray r, float tmax);

/* A copy of `scene` whose any-hit queries answer false (no_occluders set):
 * what a shading point sees when the renderer has proved that nothing lies
 * between it and a light (pack_light_view, app/pack.h). */
Scene scene_view_unoccluded(const Scene *scene);

/* The index of the material called `name`, or -1. */
int scene_find_material(const Scene *scene, const char *name);

#endif
