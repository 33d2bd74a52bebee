/* The program without the speed pack (make FAST=0): the film as film_init
 * makes it; no index, so every query tests every instance in order; every
 * scene read and parsed word by word, in one pass; every PNG
 * written by image.c's libpng rows. */
#include "app/pack.h"

bool pack_film_init(Film *film, int width, int height)
{
  return film_init(film, width, height);
}

bool pack_index(Scene *scene)
{
  scene->index = NULL;
  return true;
}

void pack_index_free(Scene *scene)
{
  scene->index = NULL;
}

bool pack_sphere_line(const char *text, const char *end, PackSphereLine *out)
{
  (void)text;
  (void)end;
  (void)out;
  return false;
}

bool pack_parse(const char *file, const char *text, size_t len, Scene *scene)
{
  (void)file;
  (void)text;
  (void)len;
  (void)scene;
  return false;
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
