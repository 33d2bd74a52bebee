/* The shared command line (step 01): every step takes the same options and
 * says which ones it ignores. README.md lists them. */
#include "app/cli.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "film.h"
#include "threads.h"
#include "app/aov.h"
#include "app/render.h"
#include "sampler.h"
#include "scene.h"

static void usage(const char *prog, const char *summary, const char *scene)
{
  printf("usage: %s [options]\n%s\n\n", prog, summary);
  printf("  --scene FILE        scene to render (default: %s)\n"
         "  -o, --output FILE   output image, .png .jpg .hdr or .pfm (default: %s.png)\n"
         "  --width W           film width in pixels, 1..%d (default: the scene's)\n"
         "  --height H          film height in pixels, 1..%d (default: the scene's)\n"
         "  --samples N         camera samples per pixel, 1..%d (steps 07-08)\n"
         "  --light-samples N   samples per area light, 1..%d (step 08)\n"
         "  --sampler NAME      center, grid, random, jitter or sobol (steps 07-08)\n"
         "  --adaptive T        adaptive sampling threshold, 0 = off (steps 07-08)\n"
         "  --threads N         render threads, 1..%d (default: " THREADS_DEFAULT ")\n"
         "  --seed S            random seed, 0..4294967295 (default 1)\n"
         "  --tonemap NAME      clamp (default), srgb or reinhard\n"
         "  -q, --quiet         no progress bar and no summary line\n"
         "  --trace X Y         render pixel (X, Y) alone and print what the step computes\n"
         "                      for it (from step 02: rays, hits, lights, terms); X from\n"
         "                      the left, Y from the top, as an image viewer shows the\n"
         "                      picture; no image is written\n"
         "  --trace-format F    text (default) or json\n"
         "  --aov NAME          draw one quantity instead of the colour: normal, depth,\n"
         "                      albedo, ambient, diffuse, specular, shadow or samples\n"
         "                      (default output: STEP.NAME.png; depth and samples are\n"
         "                      raw in .pfm/.hdr, scaled to [0, 1] in .png/.jpg)\n"
         "  -h, --help          show this text\n"
         "Values follow the option (--width 400) or an '=' (--width=400).\n\n"
         "Exit status: 0 done, 1 bad scene or failed render or write, 2 bad usage.\n",
         scene && *scene ? scene : "the step's own picture", prog, FILM_MAX_SIDE,
         FILM_MAX_SIDE, SCENE_MAX_SAMPLES, SCENE_MAX_SAMPLES, RENDER_MAX_THREADS);
}

static bool bad(const char *prog, const char *opt, const char *value, const char *want)
{
  fprintf(stderr, "%s: %s: expected %s, found '%s' (try --help)\n", prog, opt, want, value);
  return false;
}

static bool parse_int(const char *prog, const char *opt, const char *s, long lo,
                      long hi, long *out)
{
  char *end;
  errno = 0;
  long v = strtol(s, &end, 10);
  if (end == s || *end || errno || v < lo || v > hi || isspace((unsigned char)*s)) {
    char want[64];
    snprintf(want, sizeof want, "a whole number from %ld to %ld", lo, hi);
    return bad(prog, opt, s, want);
  }
  *out = v;
  return true;
}

/* Apply option `opt` with value `val`. */
static bool apply(const char *prog, const char *opt, const char *val, Options *o)
{
  long v;
  SamplerKind kind;
  if (!strcmp(opt, "--scene"))
    o->scene_path = val;
  else if (!strcmp(opt, "-o") || !strcmp(opt, "--output"))
    o->out_path = val;
  else if (!strcmp(opt, "--width") || !strcmp(opt, "--height")) {
    if (!parse_int(prog, opt, val, 1, FILM_MAX_SIDE, &v))
      return false;
    *(opt[2] == 'w' ? &o->width : &o->height) = (int)v;
  } else if (!strcmp(opt, "--samples") || !strcmp(opt, "--light-samples")) {
    if (!parse_int(prog, opt, val, 1, SCENE_MAX_SAMPLES, &v))
      return false;
    *(opt[2] == 's' ? &o->samples : &o->light_samples) = (int)v;
  } else if (!strcmp(opt, "--threads")) {
    if (!parse_int(prog, opt, val, 1, RENDER_MAX_THREADS, &v))
      return false;
    o->threads = (int)v;
  } else if (!strcmp(opt, "--seed")) {
    if (!parse_int(prog, opt, val, 0, 4294967295L, &v))
      return false;
    o->seed = (uint32_t)v;
  } else if (!strcmp(opt, "--sampler")) {
    if (!sampler_parse(val, &kind))
      return bad(prog, opt, val, "center, grid, random, jitter or sobol");
    o->sampler = val;
  } else if (!strcmp(opt, "--tonemap")) {
    if (!image_tonemap_parse(val, &o->tonemap))
      return bad(prog, opt, val, "clamp, srgb or reinhard");
  } else if (!strcmp(opt, "--trace-format")) {
    if (strcmp(val, "text") && strcmp(val, "json"))
      return bad(prog, opt, val, "text or json");
    o->trace_json = !strcmp(val, "json");
  } else if (!strcmp(opt, "--aov")) {
    AovKind aov;
    if (!aov_parse(val, &aov))
      return bad(prog, opt, val, "normal, depth, albedo, ambient, diffuse, specular, "
                 "shadow or samples");
    o->aov = (int)aov;
  } else if (!strcmp(opt, "--adaptive")) {
    char *end;
    float t = strtof(val, &end);
    if (end == val || *end || !(t >= 0.0f) || !isfinite(t))
      return bad(prog, opt, val, "a threshold >= 0");
    o->adaptive = t;
  } else {
    fprintf(stderr, "%s: unknown option '%s' (try --help)\n", prog, opt);
    return false;
  }
  return true;
}

/* True for the options that take a value. */
static bool takes_value(const char *opt)
{
  static const char *const with_value[] = {
      "--scene", "-o", "--output", "--width", "--height", "--samples",
      "--light-samples", "--threads", "--seed", "--sampler", "--tonemap", "--adaptive",
      "--trace-format", "--aov"};
  for (size_t k = 0; k < sizeof with_value / sizeof with_value[0]; k++)
    if (strcmp(opt, with_value[k]) == 0)
      return true;
  return false;
}

CliResult cli_parse(int argc, char **argv, const char *prog, const char *summary,
                    const char *default_scene, Options *o)
{
  *o = (Options){.seed = 1, .tonemap = TONEMAP_CLAMP, .adaptive = -1.0f, .trace_x = -1,
                 .trace_y = -1, .aov = -1};
  for (int k = 1; k < argc; k++) {
    char opt[32];
    const char *arg = argv[k], *eq = strchr(arg, '='), *val;
    if (!strcmp(arg, "--help") || !strcmp(arg, "-h")) {
      usage(prog, summary, default_scene);
      return CLI_DONE;
    }
    if (!strcmp(arg, "--quiet") || !strcmp(arg, "-q")) {
      o->quiet = true;
      continue;
    }
    if (!strcmp(arg, "--trace")) { /* two values: X Y */
      long x, y;
      if (k + 2 >= argc) {
        fprintf(stderr, "%s: --trace: expected X Y, found the end of the command line "
                "(try --help)\n", prog);
        return CLI_USAGE;
      }
      if (!parse_int(prog, "--trace X", argv[k + 1], 0, FILM_MAX_SIDE - 1, &x) ||
          !parse_int(prog, "--trace Y", argv[k + 2], 0, FILM_MAX_SIDE - 1, &y))
        return CLI_USAGE;
      o->trace_x = (int)x;
      o->trace_y = (int)y;
      k += 2;
      continue;
    }
    if (arg[0] != '-') {
      fprintf(stderr, "%s: unexpected argument '%s' (try --help)\n", prog, arg);
      return CLI_USAGE;
    }
    if (eq && !strncmp(arg, "--", 2) && eq - arg >= (long)sizeof opt) {
      fprintf(stderr, "%s: unknown option '%.*s' (try --help)\n", prog, (int)(eq - arg), arg);
      return CLI_USAGE;
    }
    if (eq && !strncmp(arg, "--", 2)) {
      snprintf(opt, sizeof opt, "%.*s", (int)(eq - arg), arg);
      val = eq + 1;
    } else {
      snprintf(opt, sizeof opt, "%s", arg);
      if (!takes_value(opt)) {
        fprintf(stderr, "%s: unknown option '%s' (try --help)\n", prog, arg);
        return CLI_USAGE;
      }
      if (k + 1 >= argc) {
        fprintf(stderr, "%s: %s: expected a value, found the end of the command "
                "line (try --help)\n", prog, arg);
        return CLI_USAGE;
      }
      val = argv[++k];
    }
    if (!apply(prog, opt, val, o))
      return CLI_USAGE;
  }
  if (o->trace_x >= 0 && o->aov >= 0) {
    fprintf(stderr, "%s: --trace and --aov: expected one of them, found both (try --help)\n",
            prog);
    return CLI_USAGE;
  }
  return CLI_RUN;
}
