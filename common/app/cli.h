/* The command line every step shares (--scene, -o, --width, ...).
 * Introduced in step 01; the options are listed by --help and in README.md. */
#ifndef RT_CLI_H
#define RT_CLI_H

#include <stdbool.h>
#include <stdint.h>
#include "app/image.h"

typedef struct Options {
  const char *scene_path; /* NULL: the step's default scene */
  const char *out_path;   /* NULL: STEP.png in the current directory */
  int width, height;      /* 0: from the scene */
  int samples;            /* 0: from the scene */
  int light_samples;      /* 0: from the scene */
  const char *sampler;    /* NULL: the step's default */
  int threads;            /* 0: all cores */
  uint32_t seed;          /* default 1 */
  Tonemap tonemap;        /* default clamp */
  float adaptive;         /* < 0: not given */
  bool quiet;
  int trace_x, trace_y;   /* --trace X Y (X from the left, Y from the top); -1: off */
  bool trace_json;        /* --trace-format json */
  int aov;                /* --aov NAME as an AovKind; -1: off */
} Options;

typedef enum CliResult {
  CLI_RUN,   /* options parsed, go on */
  CLI_DONE,  /* --help was printed: exit 0 */
  CLI_USAGE, /* bad usage, message printed: exit 2 */
} CliResult;

/* Parse argv. `prog`, `summary` and `default_scene` (may be empty) go into
 * the --help text. Errors print one line naming the option. */
CliResult cli_parse(int argc, char **argv, const char *prog, const char *summary,
                    const char *default_scene, Options *opt);

#endif
