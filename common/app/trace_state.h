/* The recorder behind --trace and --aov (common/app/trace.c): a copy of the
 * scene whose index records every query and answers it with the scene's own
 * index, and what has been recorded of the pixel so far. Private to
 * trace.c and aov.c. README.md, "For students". */
#ifndef RT_TRACE_STATE_H
#define RT_TRACE_STATE_H

#include "app/trace.h"

typedef struct Trace Trace;

/* A SceneIndex that records each query, then answers it with `inner` (the
 * scene's own index, or NULL for scene.c's plain loop): same answers. */
typedef struct TraceIndex {
  SceneIndex base;     /* first member: Trace.scene.index points here */
  SceneIndex *inner;
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

/* What a recorder does with what the hooks report. */
typedef enum TraceMode {
  TRACE_RECORD,  /* --trace: lines */
  TRACE_CAPTURE, /* --trace, a run on masked materials: each light's term */
  TRACE_AOV,     /* --aov: sums over the pixel */
} TraceMode;

/* One light's term in one camera sample, from a run on masked materials. */
typedef struct TraceCaptured {
  uint32_t sample;
  int light;
  bool used;
  vec3s c;
} TraceCaptured;

struct Trace {
  TraceEvents events;  /* first member: ctx->trace points here */
  TraceMode mode;
  int term;            /* TRACE_CAPTURE: the term the materials keep */
  int aov;             /* TRACE_AOV: the AovKind summed */
  bool compact;        /* several camera samples: one line per sample */
  const char *camera_doc; /* step 02's fixed camera or step 03's */
  RenderPixelFn pixel; /* the step's pixel function */
  const RenderCtx *ctx; /* the pixel's context (its camera sample) */
  Scene scene;         /* what the step renders: index = &index.base */
  TraceIndex index;
  Scene plain;         /* the same scene with its own index, unrecorded */
  Scene masked[TERM_COUNT]; /* unrecorded, materials keeping one term */
  Material *materials[TERM_COUNT]; /* owned, masked[t].materials */

  /* The pixel so far. */
  bool camera_next;    /* the next closest-hit query is a camera ray */
  int camera_rays;     /* camera rays of this pixel */
  uint32_t sample;     /* ctx->sample of the last camera ray */
  bool lit;            /* the last camera ray hit a lit shape */
  int light_shape;     /* or the shape of this light, else -1 */
  vec3s n;             /* the normal there */
  TraceLines lines;    /* what --trace prints */
  TraceLines rays;     /* shadow rays not yet shown under their light */
  int rays_blocked;    /* how many of them were blocked */
  TraceCaptured *captured[TERM_COUNT]; /* owned */
  int n_captured[TERM_COUNT], cap_captured[TERM_COUNT];

  /* --aov sums over the pixel. */
  FilmAccum sum;
  int shadow_rays, shadow_clear;
};

/* Building lines: trace_add appends an empty line (NULL when out of memory;
 * the setters then do nothing), the setters append a field to it. */
TraceLine *trace_add(TraceLines *lines, int depth, const char *key, const char *doc);
void trace_num(TraceLine *line, const char *name, double v);
void trace_vec(TraceLine *line, const char *name, vec3s v);
void trace_vec2(TraceLine *line, const char *name, vec2s v);
void trace_word(TraceLine *line, const char *name, const char *word);

/* A new, zeroed recorder (the scene copies hold cglm matrices, which want
 * more alignment than malloc gives); free it with free(). NULL when out of
 * memory. */
Trace *trace_new(void);

/* Set up `t` over `scene` (which it must outlive) for `mode`; false when out
 * of memory (one line printed). */
bool trace_init(Trace *t, const Scene *scene, TraceMode mode);
void trace_free(Trace *t);

/* Forget the previous pixel; the next closest-hit query is its camera ray. */
void trace_begin_pixel(Trace *t);

/* Read the events the hooks reported (trace.h), then the shadow rays still
 * not shown under a light, at `depth`. */
void trace_drain(Trace *t);
void trace_flush_rays(Trace *t, int depth);

/* --aov sums (common/app/aov.c): a camera ray's hit (NULL: it hit nothing). */
void aov_camera_hit(Trace *t, const TraceEvent *hit);

#endif
