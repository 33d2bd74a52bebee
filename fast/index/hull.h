/* Shadow volume of an area light: the convex hull of a shadow ray's origin
 * and the light's parallelogram, with conservative tests of shapes against
 * it, so that the shadow rays of a point toward the light test only the
 * shapes that can stop them (step 08, docs/performance.md). */
#ifndef RT_HULL_H
#define RT_HULL_H

#include "plane.h"
#include "quad.h"

enum { HULL_DIRS = 6 };

/* Everything the shadow rays from one origin toward the quad can reach. */
typedef struct ShadowHull {
  vec3s p, o;               /* the rays' origin (the hull's apex), twice */
  double corner[4][3];      /* the quad's corners, exact, in order around it */
  vec3s lo, hi;             /* box of p, o and the corners */
  vec3s dir[HULL_DIRS];     /* directions (unit) ... */
  float reach[HULL_DIRS];   /* ... and the hull's extent along each from p */
  int n_dirs;
  float margin;             /* distance that dominates every rounding error */
  double lean;              /* margin of the "rays leave the sphere" test */
  double quad_lo[3], quad_hi[3]; /* lowest / highest sample coordinate */
} ShadowHull;

/* The hull of o and the quad, for the rays from o that end on the quad,
 * or within 2^-18 of the coordinates' size of it (the sample points as the
 * shading rounds them, the shadow rays' tmax short of them), as rays
 * spawned at a shaded point within a rounding of o compute them. */
ShadowHull hull_make(vec3s o, const Quad *q);

/* False only when no such ray can hit the sphere, as sphere_hit_t computes
 * it: the sphere is clear of the hull by a margin far above rounding, or every
 * ray leaves it (the sphere the point lies on). */
bool hull_may_meet_sphere(const ShadowHull *h, vec3s c, float r);

/* False only when the box lo..hi is clear of the hull by the margin. */
bool hull_may_meet_box(const ShadowHull *h, const float lo[3], const float hi[3]);

/* False only when no such ray can hit the plane as plane_hit_t computes it. */
bool hull_may_meet_plane(const ShadowHull *h, const Plane *pl);

#endif
