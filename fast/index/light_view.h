/* A view of the scene for one point's shadow rays toward an area light: its
 * any-hit queries test only the lit shapes that may stand in the way
 * (docs/08-area-lights.md, "Points nothing can shadow"). */
#ifndef RT_LIGHT_VIEW_H
#define RT_LIGHT_VIEW_H

#include "app/pack.h"
#include "scene.h"

/* Fill view->scene with `scene` as seen by the shadow rays ray_spawn(hit, l)
 * toward the front-side points of q: when no lit shape can stop them, a view
 * with no occluders (scene_view_unoccluded); when at most PACK_VIEW_MAX may,
 * one whose shadow queries test only those (its index lives in *view);
 * otherwise the scene itself. Returns the number of shapes the view tests:
 * 0, 1 .. PACK_VIEW_MAX, or -1 for the whole scene. scene_occluded answers
 * on the view exactly as on the scene for those rays. */
int light_view_make(const Scene *scene, const Hit *hit, const Quad *q, PackView *view);

#endif
