/* Tests of --trace and --aov (common/app/trace_pixel.c, aov.c) through the step
 * binaries: the traced pixel is the rendered pixel, the terms add up to it,
 * the pictures of quantities match what the steps draw. They test the
 * tracer, whatever the steps' code: they pass in the starter too.
 * README.md, "For students"; docs/tracing.md. */
#include "check.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "app/image.h"
#include "app/trace_line.h"

#define BIN BUILD_DIR "/bin/"
#define OUT BUILD_DIR "/test-out/trace-"
#define SIZE "--width 160 --height 120"
#define DOC "README.md, \"For students\""

static const char *const STEPS[] = {"02-intersection", "03-camera", "04-phong", "05-shadows",
                                    "06-ambient", "07-antialiasing", "08-area-lights"};
enum { N_STEPS = sizeof STEPS / sizeof STEPS[0] };

/* The step's program is built and its code written: tests/run.sh names the
 * steps whose code still holds its TODO(step NN) in RT_UNWRITTEN ("06 07"),
 * and reads them as not written yet. */
static bool present(const char *step)
{
  char path[256];
  struct stat st;
  const char *unwritten = getenv("RT_UNWRITTEN");
  if (unwritten && strstr(unwritten, (char[3]){step[0], step[1], 0}))
    return false;
  snprintf(path, sizeof path, BIN "%s", step);
  return stat(path, &st) == 0;
}

/* "FN (step NN)" for the step folder or command STEP ("05-shadows", or BIN
 * "05-shadows ..."): each failing message names the function and the step
 * (tests/run.sh's verdict line reads them back). Four buffers in turn, so
 * that one message can hold two. */
static const char *at_step(const char *fn, const char *step)
{
  static char buf[4][96];
  static int next;
  if (!strncmp(step, BIN, strlen(BIN)))
    step += strlen(BIN);
  char *b = buf[next++ % 4];
  snprintf(b, sizeof buf[0], "%s (step %.2s)", fn, step);
  return b;
}

static void run_ok(const char *cmd)
{
  char quiet[1024];
  snprintf(quiet, sizeof quiet, "%s 2>/dev/null", cmd);
  int status = system(quiet);
  cr_assert(status == 0, "%s: '%s' failed (status %d)\n  read %s", at_step("main", cmd), cmd,
            status, DOC);
}

/* The JSON trace of pixel (x, y), its lines in *lines (freed by the caller). */
static void trace(const char *step, const char *options, int x, int y, TraceLines *lines)
{
  char cmd[1024], text[4096];
  snprintf(cmd, sizeof cmd, BIN "%s " SIZE " %s --trace %d %d --trace-format json 2>/dev/null",
           step, options, x, y);
  FILE *f = popen(cmd, "r");
  cr_assert(f, "%s: cannot run '%s'\n  read %s", at_step("trace_pixel", step), cmd, DOC);
  *lines = (TraceLines){0};
  bool header = fgets(text, sizeof text, f) != NULL;
  while (header && fgets(text, sizeof text, f) && text[0] != ']') {
    TraceLine line;
    cr_assert(trace_line_parse(text, &line), "%s: '%s' printed a line that is not a trace "
              "line: %s\n  read %s", at_step("trace_pixel", step), cmd, text, DOC);
    trace_lines_push(lines, &line);
  }
  cr_assert(pclose(f) == 0 && header && lines->n > 0, "%s: '%s' printed no trace\n  read %s",
            at_step("trace_pixel", step), cmd, DOC);
}

/* The last line with this key, NULL when none. */
static const TraceLine *line_of(const TraceLines *lines, const char *key)
{
  for (int k = lines->n - 1; k >= 0; k--)
    if (!strcmp(lines->line[k].key, key))
      return &lines->line[k];
  return NULL;
}

static vec3s field_vec(const TraceLine *line, const char *name)
{
  for (int k = 0; line && k < line->n_fields; k++)
    if (!strcmp(line->f[k].name, name) && line->f[k].n == 3)
      return vec_make((float)line->f[k].v[0], (float)line->f[k].v[1], (float)line->f[k].v[2]);
  cr_assert(0, "no field '%s' in the trace line '%s'", name, line ? line->key : "(none)");
  return glms_vec3_zero();
}

static float *load(const char *path, int *w, int *h)
{
  float *px;
  cr_assert(image_load(path, w, h, &px), "%s: cannot read %s\n  read %s",
            at_step("main", path + (strncmp(path, OUT, strlen(OUT)) ? 0 : strlen(OUT))), path, DOC);
  return px;
}

Test(trace, the_traced_byte_is_the_rendered_pixel_for_any_thread_count, .timeout = 300)
{
  static const int pixels[][2] = {{0, 0}, {80, 60}, {47, 75}, {115, 50}, {159, 119}, {12, 101}};
  Check c = CHECK("trace_pixel", DOC);
  mkdir(BUILD_DIR "/test-out", 0755);
  for (int s = 0; s < N_STEPS; s++)
    for (int threads = 1; threads <= 2 && present(STEPS[s]); threads++) {
      c.fn = at_step("trace_pixel", STEPS[s]);
      char cmd[512], png[256];
      snprintf(png, sizeof png, OUT "%s-%d.png", STEPS[s], threads);
      snprintf(cmd, sizeof cmd, BIN "%s " SIZE " --threads %d -q -o %s", STEPS[s], threads, png);
      run_ok(cmd);
      int w, h;
      float *px = load(png, &w, &h);
      for (size_t p = 0; p < sizeof pixels / sizeof pixels[0]; p++) {
        int x = pixels[p][0], y = pixels[p][1];
        TraceLines lines;
        trace(STEPS[s], "", x, y, &lines);
        vec3s byte = field_vec(line_of(&lines, "byte"), "rgb");
        const float *at = px + 3 * ((size_t)(h - 1 - y) * w + x);
        vec3s rendered = vec_make(roundf(255.0f * at[0]), roundf(255.0f * at[1]),
                                  roundf(255.0f * at[2]));
        CHECK_VEC(&c, rendered, byte, 0.0, "%s --trace %d %d: the byte of the trace, the "
                  "pixel of the picture rendered with %d thread(s)", STEPS[s], x, y, threads);
        trace_lines_free(&lines);
      }
      free(px);
    }
  CHECK_DONE(&c);
}

Test(trace, the_terms_add_up_to_the_colour_of_a_lit_pixel)
{
  static const struct { const char *step; int x, y; } at[] = {
      {"04-phong", 85, 50}, {"05-shadows", 100, 85}, {"06-ambient", 85, 50}};
  Check c = CHECK("trace_pixel", DOC);
  for (size_t k = 0; k < sizeof at / sizeof at[0]; k++) {
    if (!present(at[k].step))
      continue;
    c.fn = at_step("trace_pixel", at[k].step);
    TraceLines lines;
    trace(at[k].step, "", at[k].x, at[k].y, &lines);
    vec3s sum = glms_vec3_add(field_vec(line_of(&lines, "ambient"), "rgb"),
                              glms_vec3_add(field_vec(line_of(&lines, "diffuse"), "rgb"),
                                            field_vec(line_of(&lines, "specular"), "rgb")));
    CHECK_VEC(&c, field_vec(line_of(&lines, "colour"), "rgb"), sum, 1e-5,
              "%s --trace %d %d: ambient + diffuse + specular against the colour",
              at[k].step, at[k].x, at[k].y);
    trace_lines_free(&lines);
  }
  CHECK_DONE(&c);
}

/* Step 02 draws the normal 0.5 (n + 1) on its left half and 1 - t/20 on its
 * right half: the normal and depth pictures must say the same. */
Test(trace, normal_and_depth_pictures_match_what_step_02_draws)
{
  if (!present("02-intersection"))
    return;
  run_ok(BIN "02-intersection " SIZE " -q -o " OUT "02.pfm");
  run_ok(BIN "02-intersection " SIZE " -q --aov normal -o " OUT "02-normal.pfm");
  run_ok(BIN "02-intersection " SIZE " -q --aov depth -o " OUT "02-depth.pfm");
  int w, h;
  float *px = load(OUT "02.pfm", &w, &h), *n = load(OUT "02-normal.pfm", &w, &h);
  float *t = load(OUT "02-depth.pfm", &w, &h);
  Check c = CHECK(at_step("aov_render", "02"), DOC);
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++) {
      size_t k = 3 * ((size_t)j * w + i);
      if (t[k] == 0.0f) /* no hit: the background */
        continue;
      if (i < w / 2)
        CHECK_VEC(&c, vec_make(px[k], px[k + 1], px[k + 2]), vec_make(n[k], n[k + 1], n[k + 2]),
                  0.0, "pixel (%d, %d) of the left half: the normal picture", i, h - 1 - j);
      else if (px[k] > 0.0f)
        CHECK_NEAR(&c, 20.0 * (1.0 - px[k]), t[k], 1e-4 * t[k],
                   "pixel (%d, %d) of the right half: t = 20 (1 - grey)", i, h - 1 - j);
    }
  CHECK_DONE(&c);
  free(px);
  free(n);
  free(t);
}

/* On lit shapes the colour is the sum of the three terms (step 06: the
 * ambient term too); the pictures of the terms must add up to the render. */
Test(trace, the_term_pictures_add_up_to_the_render)
{
  static const char *const terms[] = {"ambient", "diffuse", "specular"};
  if (!present("06-ambient"))
    return;
  char cmd[512], path[256];
  run_ok(BIN "06-ambient " SIZE " -q -o " OUT "06.pfm");
  run_ok(BIN "06-ambient " SIZE " -q --aov albedo -o " OUT "06-albedo.pfm");
  int w, h;
  float *px = load(OUT "06.pfm", &w, &h), *albedo = load(OUT "06-albedo.pfm", &w, &h);
  float *sum = calloc((size_t)w * h * 3, sizeof *sum);
  for (int t = 0; t < 3; t++) {
    snprintf(path, sizeof path, OUT "06-%s.pfm", terms[t]);
    snprintf(cmd, sizeof cmd, BIN "06-ambient " SIZE " -q --aov %s -o %s", terms[t], path);
    run_ok(cmd);
    float *term = load(path, &w, &h);
    for (size_t k = 0; k < (size_t)w * h * 3; k++)
      sum[k] += term[k];
    free(term);
  }
  Check c = CHECK(at_step("aov_render", "06"), DOC);
  for (size_t k = 0; k < (size_t)w * h * 3; k++)
    if (albedo[k - k % 3] + albedo[k - k % 3 + 1] + albedo[k - k % 3 + 2] > 0.0f)
      CHECK_NEAR(&c, px[k], sum[k], 1e-5 + 1e-5 * fabsf(px[k]),
                 "channel %zu of 06-ambient: the sum of the three term pictures", k);
  CHECK_DONE(&c);
  free(px);
  free(albedo);
  free(sum);
}

Test(trace, shadow_and_samples_pictures_count_rays)
{
  int w, h;
  Check c = CHECK(at_step("aov_render", "04"), DOC);
  if (present("04-phong")) { /* no shadow rays yet: every light counts */
    run_ok(BIN "04-phong " SIZE " -q --aov shadow -o " OUT "04-shadow.pfm");
    float *s = load(OUT "04-shadow.pfm", &w, &h);
    for (size_t k = 0; k < (size_t)w * h * 3; k++)
      CHECK_NEAR(&c, 1.0, s[k], 0.0, "channel %zu of 04-phong's shadow picture", k);
    free(s);
  }
  if (present("07-antialiasing")) { /* --adaptive 0: the whole budget everywhere */
    c.fn = at_step("aov_render", "07");
    run_ok(BIN "07-antialiasing " SIZE " -q --samples 9 --adaptive 0 --aov samples -o "
           OUT "07-samples.pfm");
    float *s = load(OUT "07-samples.pfm", &w, &h);
    for (size_t k = 0; k < (size_t)w * h * 3; k++)
      CHECK_NEAR(&c, 9.0, s[k], 0.0, "channel %zu of 07-antialiasing's samples picture "
                 "(--samples 9 --adaptive 0)", k);
    free(s);
  }
  CHECK_DONE(&c);
}

Test(trace, the_text_trace_is_the_json_trace)
{
  if (!present("05-shadows"))
    return;
  TraceLines lines;
  trace("05-shadows", "", 80, 70, &lines);
  FILE *f = popen(BIN "05-shadows " SIZE " --trace 80 70 2>/dev/null", "r");
  cr_assert(f, "%s: cannot run 05-shadows --trace\n  read %s", at_step("trace_pixel", "05"), DOC);
  char text[4096], want[4096];
  Check c = CHECK(at_step("trace_pixel", "05"), DOC);
  cr_assert(fgets(text, sizeof text, f), "%s: 05-shadows --trace printed nothing\n  read %s", c.fn, DOC);
  for (int k = 0; k < lines.n && fgets(text, sizeof text, f); k++) {
    trace_line_text(&lines.line[k], want, sizeof want);
    text[strcspn(text, "\n")] = 0;
    CHECK_THAT(&c, !strcmp(want, text), "line %d of the text trace\n  expected %.300s\n"
               "  got      %.300s", k + 2, want, text);
  }
  pclose(f);
  trace_lines_free(&lines);
  CHECK_DONE(&c);
}

Test(trace, bad_pixels_and_options_are_usage_errors)
{
  static const char *const bad[] = {"--trace 160 0", "--trace 0 120", "--trace 5",
                                    "--trace -1 3", "--aov colour", "--trace-format xml",
                                    "--trace 1 1 --aov normal"};
  Check c = CHECK(at_step("cli_parse", "05"), DOC);
  for (size_t k = 0; k < sizeof bad / sizeof bad[0] && present("05-shadows"); k++) {
    char cmd[256];
    snprintf(cmd, sizeof cmd, BIN "05-shadows " SIZE " %s >/dev/null 2>&1", bad[k]);
    int status = system(cmd);
    CHECK_INT(&c, 2, WIFEXITED(status) ? WEXITSTATUS(status) : -1,
              "05-shadows %s: the exit status", bad[k]);
  }
  if (present("02-intersection")) {
    int status = system(BIN "02-intersection " SIZE " --aov specular >/dev/null 2>&1");
    c.fn = at_step("cli_parse", "02");
    CHECK_INT(&c, 2, WIFEXITED(status) ? WEXITSTATUS(status) : -1,
              "02-intersection --aov specular (no shading before step 04): the exit status");
  }
  CHECK_DONE(&c);
}
