/* The recorder behind --trace and --aov: a copy of the scene whose index
 * records every query (app/trace_index.h), and what the hooks (app/trace.h)
 * and the queries have reported of the pixel so far, turned into the lines
 * of a trace or the sums of an --aov. Shared by the trace_*.c files and
 * aov.c. README.md, "For students"; docs/tracing.md. */
#ifndef RT_TRACE_RECORD_H
#define RT_TRACE_RECORD_H

#include "app/trace.h"
#include "app/trace_line.h"
#include "film.h"

/* The Phong terms, in --aov's order (app/aov.h). */
typedef enum TraceTerm { TERM_AMBIENT, TERM_DIFFUSE, TERM_SPECULAR, TERM_COUNT } TraceTerm;

/* The term's name as a trace line's key: "ambient", "diffuse", "specular". */
const char *trace_term_name(TraceTerm term);

typedef struct Trace Trace;

/* A SceneIndex that records each query, then answers it with `inner` (the
 * scene's own index, or NULL for scene.c's plain loop): same answers. */
typedef struct TraceIndex {
  SceneIndex base;     /* first member: Trace.scene.index points here */
  const SceneIndex *inner;
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
  int aov;             /* TRACE_AOV: the AovKind drawn (app/aov.h) */
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

  /* --aov sums over the pixel's camera rays (a miss adds zero to normal and
   * albedo, nothing to depth) and its shadow rays. */
  FilmAccum normal, depth, albedo;
  int shadow_rays, shadow_clear;
};

/* Forget the previous pixel; the next closest-hit query is its camera ray. */
void trace_begin_pixel(Trace *t);

/* Read the events the hooks reported (trace.h), then the shadow rays still
 * not shown under a light, at `depth`. */
void trace_drain(Trace *t);
void trace_flush_rays(Trace *t, int depth);

/* --aov: add a camera ray's hit (NULL: it hit nothing) to the sums. */
void trace_sum_hit(Trace *t, const TraceEvent *hit);

#endif
