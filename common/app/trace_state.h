/* The recorder behind --trace and --aov (common/app/trace.c): a copy of the
 * scene whose index records every query and answers it with the scene's own
 * index, and what has been recorded of the pixel so far. Private to
 * trace.c and aov.c. README.md, "For students". */
#ifndef RT_TRACE_STATE_H
#define RT_TRACE_STATE_H

#include "app/trace.h"

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

struct Trace {
  bool record;         /* --trace: keep lines; --aov: only the sums below */
  int aov;             /* --aov: the AovKind being summed, -1 for --trace */
  bool compact;        /* several camera samples: one line per sample */
  const char *camera_doc; /* step 02's fixed camera or step 03's */
  RenderPixelFn pixel; /* --aov: the step's pixel function */
  Scene scene;         /* what the step renders: index = &index.base */
  TraceIndex index;
  Scene plain;         /* the same scene, unrecorded (its own index) */
  Scene masked[TERM_COUNT]; /* unrecorded, materials keeping one term */
  Material *materials[TERM_COUNT]; /* owned, masked[t].materials */

  /* The pixel so far. */
  bool camera_next;    /* the next closest-hit query is a camera ray */
  int camera_rays;     /* camera rays of this pixel */
  uint32_t sample;     /* ctx->sample of the current camera ray */
  TraceLines lines;    /* what --trace prints */
  TraceLines rays;     /* shadow rays not yet shown under their light */
  int rays_blocked;    /* how many of them were blocked */
  bool shaded;         /* the sample's terms below are known */
  vec3s colour;        /* the sample's colour (the step's shade_trace) */
  vec3s term[TERM_COUNT];
  FilmAccum term_sum[TERM_COUNT]; /* over the pixel's samples */

  /* --aov sums over the pixel. */
  FilmAccum sum;
  int hits, shadow_rays, shadow_clear;
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

/* Set up `t` over `scene` (which it must outlive); false when out of memory
 * (one line printed). */
bool trace_init(Trace *t, const Scene *scene, bool record, int aov);
void trace_free(Trace *t);

/* Forget the previous pixel; the next closest-hit query is its camera ray. */
void trace_begin_pixel(Trace *t);

/* The end of a camera sample: its shadow rays and terms shown. */
void trace_end_sample(Trace *t);

/* --aov sums (common/app/aov.c): a camera ray's hit (NULL: none), a shadow
 * ray's answer. */
void aov_camera_hit(Trace *t, const Scene *scene, const Hit *hit);
void aov_shadow_ray(Trace *t, bool blocked);

#endif
