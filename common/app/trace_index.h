/* Setting up the recorder of --trace and --aov (app/trace_record.h) over a
 * scene: a copy whose SceneIndex records each query (camera rays, shadow
 * rays, their answers) and answers it with the scene's own index, and copies
 * whose materials keep one Phong term. README.md, "For students";
 * docs/tracing.md. */
#ifndef RT_TRACE_INDEX_H
#define RT_TRACE_INDEX_H

#include "app/trace_record.h"

/* A new, zeroed recorder (the scene copies hold cglm matrices, which want
 * more alignment than malloc gives); free it with free(). NULL when out of
 * memory. */
Trace *trace_new(void);

/* Set up `t` over `scene` (which it must outlive) for `mode`; false when out
 * of memory (one line printed). */
bool trace_init(Trace *t, const Scene *scene, TraceMode mode);
void trace_free(Trace *t);

#endif
