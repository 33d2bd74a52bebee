/* --trace X Y (common/app/trace_pixel.h): pixel (X from the left, Y from the
 * top) rendered alone by the step's pixel function: first once on materials
 * that keep one term each, then once recorded (common/app/trace_record.c);
 * then the pixel's colour and the bytes its export writes. README.md, "For students"; docs/tracing.md. */
#include "app/trace_pixel.h"

#include <stdlib.h>

#include "app/render_point.h"
#include "app/trace_index.h"

static const char *tonemap_name(Tonemap tm)
{
  return tm == TONEMAP_SRGB ? "srgb" : tm == TONEMAP_REINHARD ? "reinhard" : "clamp";
}

/* The lines after the pixel function: samples spent, the pixel rendered with
 * each term alone, the colour and the bytes. */
static void end_pixel(Trace *t, const Scene *scene, const TraceRequest *req,
                      const vec3s term[TERM_COUNT], bool lit, vec3s c)
{
  trace_flush_rays(t, 1);
  if (t->compact) {
    TraceLine *line = trace_add(&t->lines, 0, "samples", TRACE_DOC_SAMPLE);
    trace_num(line, "taken", t->camera_rays);
    trace_num(line, "budget", scene->samples);
  }
  for (int k = 0; lit && k < TERM_COUNT; k++)
    trace_vec(trace_add(&t->lines, 0, trace_term_name((TraceTerm)k),
                        k == TERM_AMBIENT ? TRACE_DOC_AMBIENT : TRACE_DOC_LIGHT),
              "rgb", term[k]);
  const char *doc = TRACE_DOC_FILM; /* a light's own shape: its colour is the lesson */
  if (!t->compact && t->light_shape >= 0)
    doc = scene->lights[t->light_shape].type == LIGHT_AREA ? TRACE_DOC_AREA_SHAPE
                                                          : TRACE_DOC_LIGHT_SHAPE;
  trace_vec(trace_add(&t->lines, 0, "colour", doc), "rgb", c);
  TraceLine *line = trace_add(&t->lines, 0, "byte", TRACE_DOC_FILM);
  vec3s bytes;
  for (int k = 0; k < 3; k++)
    bytes.raw[k] = film_to_byte(c.raw[k], req->tonemap);
  trace_vec(line, "rgb", bytes);
  trace_word(line, "tonemap", tonemap_name(req->tonemap));
}

static void print(const Trace *t, const Scene *scene, const TraceRequest *req, FILE *out)
{
  int i = req->x, j = scene->height - 1 - req->y;
  if (req->json) {
    fprintf(out, "{\"step\": \"%s\", \"x\": %d, \"y\": %d, \"i\": %d, \"j\": %d, "
            "\"width\": %d, \"height\": %d, \"args\": \"", req->step, req->x, req->y, i, j,
            scene->width, scene->height);
    for (const char *c = req->args ? req->args : ""; *c; c++)
      fprintf(out, *c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
    fprintf(out, "\", \"lines\": [\n");
  } else {
    fprintf(out, "%s --trace %d %d: x %d from the left, y %d from the top of the %dx%d "
            "picture = the film's pixel (i %d, j %d), j from the bottom\n", req->step,
            req->x, req->y, req->x, req->y, scene->width, scene->height, i, j);
  }
  trace_lines_print(&t->lines, req->json, out);
  if (req->json)
    fprintf(out, "]}\n");
}

bool trace_pixel(const Scene *scene, const TraceRequest *req, FILE *out)
{
  if (req->x >= scene->width || req->y >= scene->height) {
    fprintf(stderr, "%s: --trace: expected a pixel of the %dx%d picture (X 0 to %d from "
            "the left, Y 0 to %d from the top), found %d %d\n", req->step, scene->width,
            scene->height, scene->width - 1, scene->height - 1, req->x, req->y);
    return false;
  }
  Trace *t = trace_new();
  if (!t || !trace_init(t, scene, TRACE_RECORD)) {
    if (!t)
      fprintf(stderr, "trace: out of memory\n");
    free(t);
    return false;
  }
  if (!(req->features & SCENE_CAMERA))
    t->camera_doc = TRACE_DOC_FIXED_CAMERA;
  int i = req->x, j = scene->height - 1 - req->y;
  /* A memo of its own (adaptive sampling's lattice points, step 07), each
   * run a tile of its own: the pixel traces what the render traces. */
  Film film = {.width = scene->width, .height = scene->height, .memo = render_memo_new()};
  vec3s term[TERM_COUNT];
  for (int k = 0; k < TERM_COUNT; k++) { /* unrecorded, each term alone */
    render_memo_next_tile(film.memo);
    term[k] = req->pixel(&t->masked[k], &film, i, j);
  }
  if (!(req->features & SCENE_SAMPLES))
    trace_vec2(trace_add(&t->lines, 0, "film sample", TRACE_DOC_FILM), "s",
               film_sample(&film, i, j));
  trace_begin_pixel(t);
  render_memo_next_tile(film.memo);
  vec3s c = req->pixel(&t->scene, &film, i, j);
  trace_end_sample(t);
  bool lit = (req->features & SCENE_LIGHTS) && (t->compact || t->lit);
  end_pixel(t, scene, req, term, lit, c);
  print(t, scene, req, out);
  free(film.memo);
  trace_free(t);
  free(t);
  return true;
}
