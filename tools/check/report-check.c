/* report-check: does a browser's screenshot of the report show its pictures?
 * Each <img src> of the page must appear in the screenshot pixel for pixel
 * (within 2/255 per channel), at its own size: a broken-image icon, a
 * missing file or a picture that failed to decode does not. tests/report.sh
 * runs it on headless Chromium's screenshot; docs/tracing.md, "The report".
 *
 * usage: report-check PAGE.html SCREENSHOT.png
 * Exit status: 0 every picture is shown, 1 some is not, 2 bad input. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/image.h"

typedef struct Picture {
  int w, h;
  unsigned char *px; /* RGB bytes, rows from the bottom */
} Picture;

static bool load(const char *path, Picture *p)
{
  float *rgb;
  if (!image_load(path, &p->w, &p->h, &rgb))
    return false;
  size_t n = (size_t)p->w * p->h * 3;
  p->px = malloc(n);
  for (size_t k = 0; p->px && k < n; k++)
    p->px[k] = (unsigned char)(rgb[k] * 255.0f + 0.5f);
  free(rgb);
  return p->px != NULL;
}

static bool near(const unsigned char *a, const unsigned char *b)
{
  for (int c = 0; c < 3; c++)
    if (abs(a[c] - b[c]) > 2)
      return false;
  return true;
}

/* Does `pic` appear in `shot` with its bottom-left corner at (x, y)? A few
 * spread pixels first, then all of them. */
static bool at(const Picture *shot, const Picture *pic, int x, int y)
{
  for (int pass = 0; pass < 2; pass++) {
    int step_x = pass ? 1 : pic->w / 7 + 1, step_y = pass ? 1 : pic->h / 7 + 1;
    for (int j = 0; j < pic->h; j += step_y)
      for (int i = 0; i < pic->w; i += step_x)
        if (!near(&pic->px[3 * ((size_t)j * pic->w + i)],
                  &shot->px[3 * ((size_t)(y + j) * shot->w + x + i)]))
          return false;
  }
  return true;
}

static bool shown(const Picture *shot, const Picture *pic)
{
  for (int y = 0; y + pic->h <= shot->h; y++)
    for (int x = 0; x + pic->w <= shot->w; x++)
      if (at(shot, pic, x, y))
        return true;
  return false;
}

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: report-check PAGE.html SCREENSHOT.png\n");
    return 2;
  }
  FILE *f = fopen(argv[1], "r");
  Picture shot;
  if (!f || !load(argv[2], &shot)) {
    fprintf(stderr, "report-check: cannot read %s or %s\n", argv[1], argv[2]);
    return 2;
  }
  char dir[512], line[8192], seen[256][256];
  snprintf(dir, sizeof dir, "%s", argv[1]);
  char *slash = strrchr(dir, '/');
  *(slash ? slash + 1 : dir) = 0;
  int n = 0, missing = 0;
  while (fgets(line, sizeof line, f))
    for (char *s = line; (s = strstr(s, "<img ")) && (s = strstr(s, "src=\"")); s++) {
      char src[256];
      if (sscanf(s + 5, "%255[^\"]", src) != 1)
        continue;
      bool again = false;
      for (int k = 0; k < n; k++)
        again |= !strcmp(seen[k], src);
      if (again || n == 256)
        continue;
      snprintf(seen[n++], sizeof seen[0], "%s", src);
      char path[800];
      snprintf(path, sizeof path, "%s%s", dir, src);
      Picture pic = {0};
      if (!(load(path, &pic) && shown(&shot, &pic))) {
        printf("report-check: %s is not shown in %s\n", src, argv[2]);
        missing++;
      }
      free(pic.px);
    }
  fclose(f);
  printf("report-check: %d of %d pictures of %s shown in %s\n", n - missing, n, argv[1],
         argv[2]);
  free(shot.px);
  return n > 0 && missing == 0 ? 0 : 1;
}
