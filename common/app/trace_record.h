/* The recorder behind --trace and --aov: a copy of the scene whose query
 * table records every query (app/trace_index.h) and answers it with the
 * scene's own, turned into the lines of a trace or the sums of an --aov.
 * The step's code reports nothing: the recorder sees its camera rays and
 * shadow rays in the table, and for each camera ray that hits a lit shape
 * calls the shading functions (common/shade.h) once more with the hit it
 * saw, one light at a time, to show that light's l, L_i, shadow rays and
 * terms. Shared by the trace_*.c files and aov.c. README.md, "For
 * students"; docs/tracing.md. */
#ifndef RT_TRACE_RECORD_H
#define RT_TRACE_RECORD_H

#include "app/render.h"
#include "app/trace_line.h"
#include "film.h"
#include "scene.h"
#include "scene_index.h"

/* The Phong terms, in --aov's order (app/aov.h). */
typedef enum TraceTerm { TERM_AMBIENT, TERM_DIFFUSE, TERM_SPECULAR, TERM_COUNT } TraceTerm;

/* The term's name as a trace line's key: "ambient", "diffuse", "specular". */
const char *trace_term_name(TraceTerm term);

typedef struct Trace Trace;

/* A query table that records each query, then answers it with the scene
 * `inner` (scene_closest, scene_any): the same answers. */
typedef struct TraceIndex {
  SceneIndex base;     /* first member: Trace.scene.index points here */
  const Scene *inner;
  struct Trace *trace;
} TraceIndex;

/* Where the doc explains each quantity of a trace. */
#define TRACE_DOC_FILM "docs/01-film.md, \"The math\""
#define TRACE_DOC_HIT "docs/02-intersection.md, \"The math\""
#define TRACE_DOC_FIXED_CAMERA "docs/02-intersection.md, \"The math\""
#define TRACE_DOC_CAMERA "docs/03-camera.md, \"The math\""
#define TRACE_DOC_LIGHT "docs/04-phong.md, \"The math\""
#define TRACE_DOC_SHADOW "docs/05-shadows.md, \"Self-intersection: where the shadow ray starts\""
#define TRACE_DOC_AMBIENT "docs/06-ambient.md, \"The math\""
#define TRACE_DOC_SAMPLE "docs/07-antialiasing.md, \"The math\""
#define TRACE_DOC_AREA "docs/08-area-lights.md, \"The estimate: N point lights\""
#define TRACE_DOC_LIGHT_SHAPE "docs/06-ambient.md, \"Lights the camera sees\""
#define TRACE_DOC_AREA_SHAPE "docs/08-area-lights.md, \"The light\""

/* What a recorder does with the queries it sees. */
typedef enum TraceMode {
  TRACE_RECORD,  /* --trace: lines */
  TRACE_AOV,     /* --aov: sums over the pixel */
} TraceMode;

struct Trace {
  RenderWatch watch;   /* first member: --aov's render calls the pixel here */
  TraceMode mode;
  int aov;             /* TRACE_AOV: the AovKind drawn (app/aov.h) */
  bool compact;        /* several camera samples: one line per sample */
  const char *camera_doc; /* step 02's fixed camera or step 03's */
  Scene scene;         /* what the step renders: index = &index.base */
  TraceIndex index;
  Scene plain;         /* the same scene, unrecorded */
  Scene masked[TERM_COUNT]; /* unrecorded, materials keeping one term */
  Material *materials[TERM_COUNT]; /* owned, masked[t].materials */

  /* The pixel so far. */
  bool camera_next;    /* the next closest-hit query is a camera ray */
  bool replaying;      /* the shading functions called again for one light:
                        * their shadow rays are that light's */
  int camera_rays;     /* camera rays of this pixel */
  bool lit;            /* the last camera ray hit a lit shape */
  bool pending;        /* and its lights are still to be shown */
  int light_shape;     /* or the shape of this light, else -1 */
  Hit hit;             /* the last camera ray's hit, when lit */
  vec3s eye;           /* and where that ray started */
  TraceLines lines;    /* what --trace prints */
  TraceLines rays;     /* shadow rays not yet shown under their light */
  int rays_blocked;    /* how many of them were blocked */

  /* --aov sums over the pixel's camera rays (a miss adds zero to normal and
   * albedo, nothing to depth) and its shadow rays. */
  FilmAccum normal, depth, albedo;
  int shadow_rays, shadow_clear;
};

/* Forget the previous pixel; the next closest-hit query is its camera ray. */
void trace_begin_pixel(Trace *t);

/* The lights of the last camera ray's hit, each shaded once more (--trace);
 * called at each camera ray and after the pixel. */
void trace_end_sample(Trace *t);

/* The shadow rays still not shown under a light, at `depth`. */
void trace_flush_rays(Trace *t, int depth);

/* A camera ray's hit (NULL: it hit nothing), seen by the table: noted for
 * the lights, its fields on the closest-hit line, or added to --aov's sums. */
void trace_on_hit(Trace *t, const Hit *hit);

#endif
