/* --aov NAME: one quantity of the render as a picture (an "arbitrary output
 * variable"), for every step from 02: the hit's normal, depth and albedo, the
 * Phong terms one at a time, the fraction of shadow rays that reach their
 * light, the samples spent. Recorded from the scene's query table
 * (common/app/trace_record.h) while the step's own pixel function renders. README.md, "For students". */
#ifndef RT_AOV_H
#define RT_AOV_H

#include "app/render.h"

typedef enum AovKind {
  AOV_NORMAL,   /* 0.5 (n + 1) of the camera ray's hit, black for a miss */
  AOV_DEPTH,    /* the hit's distance t (mean over the samples that hit) */
  AOV_ALBEDO,   /* the hit material's diffuse colour */
  AOV_AMBIENT,  /* the Phong terms alone, on lit shapes: m_amb l_amb, */
  AOV_DIFFUSE,  /* the lights' m_dif L_i (n.l), */
  AOV_SPECULAR, /* the lights' m_spe L_i max(0, r.v)^shi */
  AOV_SHADOW,   /* shadow rays that reach their light / shadow rays traced */
  AOV_SAMPLES,  /* camera samples spent on the pixel */
  AOV_COUNT
} AovKind;

/* Parse an AOV name ("normal", ..., "samples"); false when unknown. */
bool aov_parse(const char *name, AovKind *out);
const char *aov_name(AovKind aov);

/* The Phong term (TraceTerm) an AOV shows, -1 for the others. */
int aov_term(int aov);

/* Render `aov` into `film` (same size as the scene) with the step's `pixel`
 * function: each pixel is rendered as usual and the quantity recorded. The
 * values are raw (t in scene units, samples as a count). False (one line
 * printed) when out of memory. */
bool aov_render(const Scene *scene, RenderPixelFn pixel, const RenderSettings *set,
                AovKind aov, Film *film, RenderStats *stats);

/* True when `path` names an 8-bit file (.png, .jpg): not .pfm or .hdr. */
bool aov_file_is_bytes(const char *path);

/* For an 8-bit file: depth as t_near / t (the nearest hit white, misses
 * black), samples as a fraction of `budget`; the others are already in
 * [0, 1]. */
void aov_for_bytes(AovKind aov, int budget, Film *film);

#endif
