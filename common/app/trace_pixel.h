/* `--trace X Y` (every step from 02): one pixel rendered alone by the step's
 * pixel function, and what it computed printed line by line (rays, hits,
 * lights, terms, the colour and its bytes). README.md, "For students";
 * docs/tracing.md. */
#ifndef RT_TRACE_PIXEL_H
#define RT_TRACE_PIXEL_H

#include <stdio.h>

#include "app/render.h"

/* What --trace asks for. */
typedef struct TraceRequest {
  const char *step;    /* "05-shadows" */
  unsigned features;   /* the step's SceneFeature bits */
  RenderPixelFn pixel; /* the step's pixel function */
  int x, y;            /* pixel, x from the left, y from the top */
  Tonemap tonemap;
  bool json;           /* JSON lines instead of indented text */
  const char *args;    /* the other options of the command line (JSON header) */
} TraceRequest;

/* Render pixel (x, y) alone through req->pixel, recording every step, and
 * print the trace to `out`. False (one line printed) when (x, y) is outside
 * the film or memory runs out. */
bool trace_pixel(const Scene *scene, const TraceRequest *req, FILE *out);

#endif
