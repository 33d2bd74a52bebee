/* The speed pack behind common/app/pack.h, linked by default (FAST=1):
 * the film in huge pages (memory/), the scene's index and its shadow
 * culling toward area lights (index/), the large scene's sphere lines and
 * its parts parsed at once (reader/), PNG in parallel bands (png/). */
#include "app/pack.h"

#include "index/accel.h"
#include "memory/huge.h"
#include "png/bands.h"
#include "reader/mapped.h"
#include "reader/parts.h"
#include "reader/sphere_line.h"

bool pack_film_init(Film *film, int width, int height)
{
  float *rgb = huge_zeroed((size_t)width * height * 3 * sizeof *rgb);
  if (!rgb) /* small, or no memory: film_init says which */
    return film_init(film, width, height);
  *film = (Film){.width = width, .height = height, .rgb = rgb};
  return true;
}

bool pack_index(Scene *scene)
{
  return accel_build(scene);
}

void pack_index_free(Scene *scene)
{
  accel_free(scene);
}

bool pack_sphere_line(const char *text, const char *end, PackSphereLine *out)
{
  return sphere_line_read(text, end, out);
}

bool pack_parse(const char *file, const char *text, size_t len, Scene *scene)
{
  return parts_parse(file, text, len, scene);
}

bool pack_map(int fd, size_t size, char **text)
{
  return mapped_open(fd, size, text);
}

void pack_unmap(char *text, size_t size)
{
  mapped_close(text, size);
}

int pack_png(FILE *f, int w, int h, PackRowFn row, const void *picture)
{
  return bands_write_png(f, w, h, row, picture) ? 1 : 0;
}
