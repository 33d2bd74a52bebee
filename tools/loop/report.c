/* report: build/report/index.html, the page a student opens after make test
 * or make test-step N: per step and check PASS or FAIL and why (the results
 * files tests/run.sh writes), the picture expected | yours | difference with
 * a flip between the first two, the Phong terms when the image test compared
 * them, and the --trace commands of the worst pixels (what tests/terms.h
 * wrote in build/report/STEP/). A static page, no JavaScript; the page's look
 * is tools/loop/report.html. README.md, "For students".
 *
 * usage: report BUILD TEMPLATE [NAME...]   (writes BUILD/report/index.html;
 * with NAMEs, only those steps or test binaries) */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json.h"

enum { NAMES = 64 };

static char *slurp(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f)
    return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  rewind(f);
  char *buf = malloc((size_t)n + 1);
  if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
    free(buf);
    buf = NULL;
  }
  if (buf)
    buf[n] = 0;
  fclose(f);
  return buf;
}

static void html(FILE *out, const char *s)
{
  for (; *s; s++)
    if (*s == '<')
      fputs("&lt;", out);
    else if (*s == '>')
      fputs("&gt;", out);
    else if (*s == '&')
      fputs("&amp;", out);
    else if (*s == '"')
      fputs("&quot;", out);
    else
      fputc(*s, out);
}

/* The steps and test binaries: results files and report folders, sorted. */
static int names(const char *build, char name[NAMES][64])
{
  char dir[512];
  int n = 0;
  for (int pass = 0; pass < 2; pass++) {
    snprintf(dir, sizeof dir, "%.200s/%s", build, pass ? "report" : "results");
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d)) && n < NAMES;) {
      char base[64];
      snprintf(base, sizeof base, "%.63s", e->d_name);
      char *dot = strstr(base, ".json");
      if (e->d_name[0] == '.' || (pass == 0 && !dot) || (pass == 1 && strchr(base, '.')))
        continue;
      if (dot)
        *dot = 0;
      bool seen = false;
      for (int k = 0; k < n; k++)
        seen |= !strcmp(name[k], base);
      if (!seen)
        snprintf(name[n++], 64, "%s", base);
    }
    if (d)
      closedir(d);
  }
  qsort(name, (size_t)n, 64, (int (*)(const void *, const void *))strcmp);
  return n;
}

static void verdict(FILE *out, bool pass)
{
  fprintf(out, "<span class=\"%s\">%s</span>", pass ? "pass" : "fail", pass ? "PASS" : "FAIL");
}

/* The checks of one results file, and the messages of the failing tests. */
static void checks(FILE *out, const Json *res)
{
  fputs("<table class=\"checks\">\n", out);
  for (const Json *c = json_get(res, "checks") ? json_get(res, "checks")->child : NULL; c;
       c = c->next) {
    fputs("<tr><td>", out);
    verdict(out, json_true(c, "pass"));
    fputs("</td><td>", out);
    html(out, json_text(c, "check"));
    fputs("</td><td>", out);
    html(out, json_text(c, "verdict"));
    fputs("</td></tr>\n", out);
    const Json *fails = json_get(c, "failures");
    for (const Json *f = fails ? fails->child : NULL; f; f = f->next) {
      fputs("<tr><td></td><td colspan=\"2\"><details><summary>", out);
      html(out, json_text(f, "test"));
      fputs("</summary><pre>", out);
      const Json *msgs = json_get(f, "messages");
      for (const Json *m = msgs ? msgs->child : NULL; m; m = m->next) {
        html(out, m->text ? m->text : "");
        fputs("\n", out);
      }
      fputs("</pre></details></td></tr>\n", out);
    }
  }
  fputs("</table>\n", out);
}

/* expected | yours | difference | flip, for the pictures prefix.*.png. */
static void pictures(FILE *out, const char *step, const char *prefix, const char *caption)
{
  fprintf(out, "<div class=\"pictures\">\n");
  static const char *const kinds[] = {"expected", "yours", "diff"};
  static const char *const titles[] = {"expected", "yours", "difference (x8, red: over)"};
  for (int k = 0; k < 3; k++)
    fprintf(out, "<figure><img src=\"%s/%s.%s.png\" alt=\"%s: %s\"><figcaption>%s %s"
            "</figcaption></figure>\n", step, prefix, kinds[k], caption, titles[k], caption,
            titles[k]);
  fprintf(out, "<figure class=\"flip\"><input type=\"checkbox\" id=\"flip-%s-%s\">"
          "<div class=\"stack\"><img class=\"yours\" src=\"%s/%s.yours.png\" alt=\"yours\">"
          "<img class=\"expected\" src=\"%s/%s.expected.png\" alt=\"expected\"></div>"
          "<figcaption><label for=\"flip-%s-%s\">flip: hover or click to see "
          "<span class=\"to-expected\">expected</span><span class=\"to-yours\">yours"
          "</span></label></figcaption></figure>\n</div>\n",
          step, prefix, step, prefix, step, prefix, step, prefix);
}

/* The image test's details (tests/terms.h's image.txt) and its pictures. */
static void image(FILE *out, const char *build, const char *step)
{
  char path[512], line[1024], key[32];
  snprintf(path, sizeof path, "%.200s/report/%.64s/image.txt", build, step);
  FILE *f = fopen(path, "r");
  if (!f)
    return;
  double tol = 0, fraction = 0, max = 0, over = 0, got_max = 0, rmse = 0;
  char trace[768] = "";
  int pass = 1, terms = 0;
  fputs("<h3>The picture</h3>\n", out);
  while (fgets(line, sizeof line, f)) {
    line[strcspn(line, "\n")] = 0;
    if (sscanf(line, "%31s", key) != 1)
      continue;
    const char *rest = line + strlen(key) + 1;
    if (!strcmp(key, "pass"))
      pass = atoi(rest);
    else if (!strcmp(key, "tolerance"))
      sscanf(rest, "%lf %lf %lf", &tol, &fraction, &max);
    else if (!strcmp(key, "measured"))
      sscanf(rest, "%lf %lf %lf", &over, &got_max, &rmse);
    else if (!strcmp(key, "trace"))
      snprintf(trace, sizeof trace, "%s", rest);
    else if (!strcmp(key, "term")) {
      char name[32];
      int ok, x, y;
      double t_over, t_max, t_rmse;
      if (sscanf(rest, "%31s %d %lf %lf %lf %d %d", name, &ok, &t_over, &t_max, &t_rmse, &x,
                 &y) != 7)
        continue;
      if (!terms++)
        fputs("<h3>The Phong terms, each drawn alone (--aov)</h3>\n", out);
      fprintf(out, "<p>");
      verdict(out, ok);
      fprintf(out, " <b>%s</b>: %.2f%% of channels over %.1f/255, largest %.1f/255 at "
              "(%d, %d), rmse %.2f/255</p>\n", name, 100.0 * t_over, tol, t_max, x, y, t_rmse);
      pictures(out, step, name, name);
    }
    if (!strcmp(key, "measured")) {
      fprintf(out, "<p>");
      verdict(out, pass);
      fprintf(out, " tolerance: each channel within %.1f/255, except at most %.2f%% of "
              "channels, none beyond %.0f/255. Measured: %.3f%% over, largest %.1f/255, rmse "
              "%.2f/255.</p>\n", tol, 100.0 * fraction, max, 100.0 * over, got_max, rmse);
      pictures(out, step, "image", "the picture");
    }
  }
  fclose(f);
  if (*trace) {
    fputs("<p>Trace the pixel that differs most: <code>", out);
    html(out, trace);
    fputs("</code></p>\n", out);
  }
}

/* The image test's verdict from image.txt: 1 passed, 0 failed, -1 none. */
static int image_passed(const char *build, const char *step)
{
  char path[512];
  int pass = -1;
  snprintf(path, sizeof path, "%.200s/report/%.64s/image.txt", build, step);
  FILE *f = fopen(path, "r");
  if (f && fscanf(f, "pass %d", &pass) != 1)
    pass = -1;
  if (f)
    fclose(f);
  return pass;
}

static void section(FILE *out, const char *build, const char *step)
{
  char path[512];
  snprintf(path, sizeof path, "%.200s/results/%.64s.json", build, step);
  char *text = slurp(path);
  Json *res = calloc(1, sizeof *res);
  bool have = text && json_value(text, res);
  fprintf(out, "<section id=\"%s\">\n<h2>%s ", step, step);
  int image_pass = image_passed(build, step);
  /* A step whose code still holds its TODO(step NN) (tests/run.sh). */
  const char *todo = have ? json_text(res, "not_written") : NULL;
  if (todo && *todo)
    fputs("<span class=\"fail\">TODO</span>", out);
  else if (have || image_pass >= 0) /* without a results file: the image test's */
    verdict(out, have ? json_true(res, "pass") : image_pass);
  fputs("</h2>\n", out);
  if (todo && *todo) {
    fputs("<p>not written yet: ", out);
    html(out, todo);
    fputs(" still holds its TODO</p>\n", out);
  } else if (have)
    checks(out, res);
  image(out, build, step);
  fputs("</section>\n", out);
  json_free(res);
  free(text);
}

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: report BUILD TEMPLATE [NAME...]\n");
    return 2;
  }
  const char *build = argv[1];
  char *tmpl = slurp(argv[2]), path[512], name[NAMES][64];
  char *mark = tmpl ? strstr(tmpl, "<!-- steps -->") : NULL;
  if (!mark) {
    fprintf(stderr, "report: %s: expected a template with '<!-- steps -->'\n", argv[2]);
    return 1;
  }
  snprintf(path, sizeof path, "%.200s/report/index.html", build);
  FILE *out = fopen(path, "w");
  if (!out) {
    fprintf(stderr, "report: cannot write %s\n", path);
    return 1;
  }
  fwrite(tmpl, 1, (size_t)(mark - tmpl), out);
  int n = argc > 3 ? 0 : names(build, name);
  for (int k = 3; k < argc && n < NAMES; k++)
    snprintf(name[n++], 64, "%.63s", argv[k]);
  fputs("<nav>", out);
  for (int k = 0; k < n; k++)
    fprintf(out, "<a href=\"#%s\">%s</a> ", name[k], name[k]);
  fputs("</nav>\n", out);
  for (int k = 0; k < n; k++)
    section(out, build, name[k]);
  fputs(mark, out);
  fclose(out);
  free(tmpl);
  printf("report: %s (open it in a browser)\n", path);
  return 0;
}
