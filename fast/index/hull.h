/* Shadow volume of an area light: the convex hull of a shaded point and the
 * light's parallelogram, with conservative tests of shapes against it, so that
 * a point no shape can shadow skips its shadow rays (step 08,
 * docs/08-area-lights.md and docs/performance.md). */
#ifndef RT_HULL_H
#define RT_HULL_H

#include "plane.h"
#include "quad.h"

enum { HULL_DIRS = 6 };

/* Everything the shadow rays spawned at a hit toward the quad can reach. */
typedef struct ShadowHull {
  vec3s p, o;               /* shaded point, the rays' origin (ray_spawn) */
  double corner[4][3];      /* the quad's corners, exact, in order around it */
  vec3s lo, hi;             /* box of p, o and the corners */
  vec3s dir[HULL_DIRS];     /* directions (unit) ... */
  float reach[HULL_DIRS];   /* ... and the hull's extent along each from p */
  int n_dirs;
  float margin;             /* distance that dominates every rounding error */
  double lean;              /* margin of the "rays leave the sphere" test */
  double quad_lo[3], quad_hi[3]; /* lowest / highest sample coordinate */
} ShadowHull;

/* The hull of the hit point and the quad, for the rays ray_spawn(hit, l) that
 * go to the front side of hit->n. */
ShadowHull hull_make(const Hit *hit, const Quad *q);

/* False only when no such ray can hit the sphere, as sphere_hit_t computes
 * it: the sphere is clear of the hull by a margin far above rounding, or every
 * ray leaves it (the sphere the point lies on). */
bool hull_may_meet_sphere(const ShadowHull *h, vec3s c, float r);

/* False only when the box lo..hi is clear of the hull by the margin. */
bool hull_may_meet_box(const ShadowHull *h, const float lo[3], const float hi[3]);

/* False only when no such ray can hit the plane as plane_hit_t computes it. */
bool hull_may_meet_plane(const ShadowHull *h, const Plane *pl);

#endif
