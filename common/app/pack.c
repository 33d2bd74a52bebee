/* The program without the speed pack (make FAST=0): the film as film_init
 * makes it; no index, so every query tests every instance in order; every
 * shadow ray traced; every scene read and parsed in one pass; every PNG
 * written by image.c's libpng rows. */
#include "app/pack.h"

bool pack_film_init(Film *film, int width, int height)
{
  return film_init(film, width, height);
}

bool pack_index(Scene *scene)
{
  (void)scene;
  return true;
}

int pack_light_view(const Scene *scene, const Hit *hit, const Quad *q,
                    const RenderSettings *set, PackView *view)
{
  (void)hit;
  (void)q;
  (void)set;
  view->scene = *scene;
  return scene->light_samples;
}

bool pack_parse(const char *file, const char *text, size_t len, Scene *scene, bool *ok)
{
  (void)file;
  (void)text;
  (void)len;
  (void)scene;
  (void)ok;
  return false;
}

bool pack_lines(struct Parser *p)
{
  (void)p;
  return true;
}

bool pack_map(int fd, size_t size, char **text)
{
  (void)fd;
  (void)size;
  (void)text;
  return false;
}

void pack_unmap(char *text, size_t size)
{
  (void)text;
  (void)size;
}

int pack_png(FILE *f, int w, int h, PackRowFn row, const void *picture)
{
  (void)f;
  (void)w;
  (void)h;
  (void)row;
  (void)picture;
  return -1;
}
