/* The scene's query table: what scene_intersect and scene_occluded go
 * through, for whoever fills one (the speed pack's index, app/pack.h) or
 * wraps one (the render's counting, --trace's recording), and the dispatch
 * from an instance to its shape's functions. The student's code never needs
 * it. docs/performance.md, "The scene queries". */
#ifndef RT_SCENE_INDEX_H
#define RT_SCENE_INDEX_H

#include "box.h"
#include "shapes.h"

/* The scene (scene.h), by pointer only: the table's users include scene.h
 * themselves, and scene.c, which fills Scene.index, includes this. */
typedef struct Scene Scene;

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
   * stack, a stalled load per camera ray (docs/performance.md). */
  const Instance *(*closest)(const Scene *scene, const Ray *r, float *tmax);
  /* True when some lit shape lies on the ray with t in (0, tmax). */
  bool (*any)(const Scene *scene, const Ray *r, float tmax);
} SceneIndex;

/* The query table's answers (scene->index's, or without one every instance
 * tested in order): the closest instance with t in (0, *tmax), *tmax becoming
 * its distance, NULL when none; whether some lit shape lies on the ray with t
 * in (0, tmax). What scene_intersect and scene_occluded ask; a wrapper around
 * the table (the render's counting, --trace's recording) answers with them. */
const Instance *scene_closest(const Scene *scene, const Ray *r, float *tmax);
bool scene_any(const Scene *scene, const Ray *r, float tmax);

/* Distance to one instance along the ray with t in (0, tmax), INFINITY when
 * missed: its shape's name_hit_t (the student's sphere_hit_t, plane_hit_t;
 * the given quad_hit_t, disc_hit_t, ...). */
float scene_instance_hit_t(const Instance *inst, Ray r, float tmax);

/* The box of an instance's shape (sphere_bounds, plane_bounds, ...):
 * infinite along the axes an unbounded shape extends in (box_is_bounded). */
Box scene_instance_bounds(const Instance *inst);

/* The shape's name, as the statement that makes it is written ("sphere");
 * a quad is an area light's. */
const char *scene_shape_name(ShapeType shape);

#endif
