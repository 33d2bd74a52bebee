/* What the image test (tests/image_test.c) adds for the student: the pictures
 * of the report (build/report/STEP/: expected, yours, difference, and the
 * details tools/loop/report.c reads), and, when the picture is wrong, the Phong
 * terms compared one by one (--aov TERM against images/STEP.TERM.png): which
 * differs most, where, and the --trace command for that pixel.
 * docs/tracing.md; README.md, "For students". */
#ifndef RT_TERMS_H
#define RT_TERMS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "app/image.h"

#define TERMS_REPORT_DIR BUILD_DIR "/report/" STEP_NAME

/* How far a render is from its reference: the share of channels over the
 * tolerance, the largest and rms differences (in 1/255), and the pixel with
 * the largest one (x from the left, y from the top, as --trace counts). */
typedef struct TermsDiff {
  double over, max, rmse;
  int x, y;
} TermsDiff;

/* Compare clamped floats with a reference (both rows from the bottom). */
static inline TermsDiff terms_diff(int w, int h, const float *out, const float *ref, double tol)
{
  TermsDiff d = {0};
  double sum = 0.0;
  long over = 0;
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++)
      for (int c = 0; c < 3; c++) {
        size_t k = ((size_t)j * w + i) * 3 + c;
        double e = 255.0 * fabs((double)out[k] - (double)ref[k]);
        e = e == e ? e : 1e9; /* NaN: as far as it gets */
        sum += e * e;
        over += e > tol;
        if (e > d.max) {
          d.max = e;
          d.x = i;
          d.y = h - 1 - j;
        }
      }
  d.over = (double)over / (3.0 * w * h);
  d.rmse = sqrt(sum / (3.0 * w * h));
  return d;
}

/* Clamp to [0, 1] as the PNG export does (NaN far outside). */
static inline void terms_clamp(float *px, size_t n)
{
  for (size_t k = 0; k < n; k++)
    px[k] = px[k] != px[k] ? 1e9f : fminf(fmaxf(px[k], 0.0f), 1.0f);
}

/* The report's three pictures: prefix.expected.png, prefix.yours.png and
 * prefix.diff.png (|yours - expected| x 8, red over the tolerance). */
static inline void terms_pictures(const char *prefix, int w, int h, const float *out,
                                  const float *ref, double tol)
{
  char path[600];
  mkdir(BUILD_DIR "/report", 0755);
  mkdir(TERMS_REPORT_DIR, 0755);
  snprintf(path, sizeof path, "%s.expected.png", prefix);
  image_save(path, w, h, ref, TONEMAP_CLAMP);
  snprintf(path, sizeof path, "%s.yours.png", prefix);
  image_save(path, w, h, out, TONEMAP_CLAMP);
  snprintf(path, sizeof path, "%s.diff.png", prefix);
  image_save_diff(path, w, h, out, ref, (float)(tol / 255.0), 8.0f);
}

/* Render term `term` with the step's --aov at w x h (options `args`) and
 * compare it with images/STEP.TERM.png; false when there is no reference or
 * no render. */
static inline bool terms_one(const char *term, int w, int h, const char *args, double tol,
                             TermsDiff *d)
{
  char ref_path[256], out_path[256], cmd[1024], prefix[512];
  snprintf(ref_path, sizeof ref_path, "images/%s.%s.png", STEP_NAME, term);
  snprintf(out_path, sizeof out_path, BUILD_DIR "/test-out/%s.%s.pfm", STEP_NAME, term);
  struct stat st;
  if (stat(ref_path, &st) != 0)
    return false;
  snprintf(cmd, sizeof cmd, BUILD_DIR "/bin/" STEP_NAME " --width %d --height %d --threads 2 "
           "--quiet %s --aov %s -o %s 2>/dev/null", w, h, args, term, out_path);
  int status = system(cmd), rw, rh, ow, oh;
  float *ref = NULL, *out = NULL;
  bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && image_load(ref_path, &rw, &rh, &ref) &&
            image_load(out_path, &ow, &oh, &out) && rw == w && rh == h && ow == w && oh == h;
  if (ok) {
    terms_clamp(out, (size_t)w * h * 3);
    *d = terms_diff(w, h, out, ref, tol);
    snprintf(prefix, sizeof prefix, TERMS_REPORT_DIR "/%s", term);
    terms_pictures(prefix, w, h, out, ref, tol);
  }
  free(ref);
  free(out);
  return ok;
}

/* After the image test: the report's pictures and details, and when it
 * failed, the terms compared. `msg` receives what the student should read
 * (empty when it passed). tol and max in 1/255, fraction a share. With
 * RT_TERMS=0 in the environment the terms are not rendered: check-regions
 * and check-starter read only the verdict, and rendering each term again
 * would take most of a failing image test's time. */
static inline void terms_after_image_test(int w, int h, const float *out, const float *ref,
                                          double tol, double fraction, double max,
                                          bool pass, const char *args, char *msg, size_t size)
{
  static const char *const TERMS[] = {"ambient", "diffuse", "specular"};
  TermsDiff all = terms_diff(w, h, out, ref, tol);
  terms_pictures(TERMS_REPORT_DIR "/image", w, h, out, ref, tol);
  char trace[512];
  snprintf(trace, sizeof trace, BUILD_DIR "/bin/" STEP_NAME " --width %d --height %d%s%s "
           "--trace %d %d", w, h, *args ? " " : "", args, all.x, all.y);
  FILE *f = fopen(TERMS_REPORT_DIR "/image.txt", "w");
  if (f)
    fprintf(f, "pass %d\ntolerance %g %g %g\nmeasured %g %g %g\nworst %d %d\n", pass, tol,
            fraction, max, all.over, all.max, all.rmse, all.x, all.y);
  msg[0] = 0;
  int worst = -1, len = 0;
  TermsDiff d[3];
  const char *want = getenv("RT_TERMS");
  bool terms = !(want && strcmp(want, "0") == 0);
  for (int k = 0; !pass && terms && k < 3; k++) {
    if (!terms_one(TERMS[k], w, h, args, tol, &d[k]))
      continue;
    bool ok = d[k].over <= fraction && d[k].max <= max;
    if (!ok && (worst < 0 || d[k].rmse > d[worst].rmse))
      worst = k;
    if (f)
      fprintf(f, "term %s %d %g %g %g %d %d\n", TERMS[k], ok, d[k].over, d[k].max, d[k].rmse,
              d[k].x, d[k].y);
    len += snprintf(msg + len, size - (size_t)len, "%s    %-9s %s: %.2f%% of channels over "
                    "%.1f/255, largest %.1f/255 at (%d, %d), rmse %.2f/255",
                    len ? "\n" : "  the Phong terms, each drawn alone (--aov TERM) against "
                    "images/" STEP_NAME ".TERM.png:\n", TERMS[k], ok ? "agrees" : "DIFFERS",
                    100.0 * d[k].over, tol, d[k].max, d[k].x, d[k].y, d[k].rmse);
  }
  if (!pass && worst >= 0) {
    snprintf(trace, sizeof trace, BUILD_DIR "/bin/" STEP_NAME " --width %d --height %d%s%s "
             "--trace %d %d", w, h, *args ? " " : "", args, d[worst].x, d[worst].y);
    len += snprintf(msg + len, size - (size_t)len, "\n  the term that differs most: %s, "
                    "worst at pixel (%d, %d) (x from the left, y from the top)",
                    TERMS[worst], d[worst].x, d[worst].y);
  } else if (!pass && len) {
    len += snprintf(msg + len, size - (size_t)len, "\n  every term agrees: what differs is "
                    "outside them (the background, a light's own shape, the sampling)");
  }
  if (!pass && strcmp(STEP_NAME, "01-film"))
    snprintf(msg + len, size - (size_t)len, "%s  trace the worst pixel: %s\n  and compare "
             "traces with the solution's: make trace-step %d", len ? "\n" : "", trace,
             atoi(STEP_NAME));
  if (f) {
    fprintf(f, "blame %s\ntrace %s\n", worst >= 0 ? TERMS[worst] : "-", trace);
    fclose(f);
  }
}

#endif
