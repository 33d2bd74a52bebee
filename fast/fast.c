/* The speed pack behind common/app/pack.h, linked by default (FAST=1):
 * the film in huge pages (memory/), the scene's index (index/), the area
 * lights' shadow views (index/light_view.c), the large scene's reader
 * (reader/), PNG in parallel bands (png/). */
#include "app/pack.h"

#include "index/accel.h"
#include "index/light_view.h"
#include "memory/huge.h"
#include "png/bands.h"
#include "reader/mapped.h"
#include "reader/pieces.h"
#include "reader/sphere_line.h"
#include "sampler.h"

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

/* The view pays only with more samples than SHADOW_VIEW_MIN_SAMPLES. With
 * the grid, a point nothing can shadow takes a quarter of the samples, at
 * least GRID_UNOCCLUDED_MIN: without a shadow edge the light's term is
 * smooth, and the grid's error on it small (docs/08-area-lights.md). */
enum { SHADOW_VIEW_MIN_SAMPLES = 4, GRID_UNOCCLUDED_MIN = 16 };

int pack_light_view(const Scene *scene, const Hit *hit, const Quad *q,
                    const RenderSettings *set, PackView *view)
{
  int n = scene->light_samples;
  if (n <= SHADOW_VIEW_MIN_SAMPLES) {
    view->scene = *scene;
    return n;
  }
  int few = n / 4 > GRID_UNOCCLUDED_MIN ? n / 4 : GRID_UNOCCLUDED_MIN;
  if (light_view_make(scene, hit, q, view) == 0 && set->sampler == SAMPLER_GRID && few < n)
    n = few;
  return n;
}

bool pack_parse(const char *file, const char *text, size_t len, Scene *scene, bool *ok)
{
  return pieces_parse(file, text, len, scene, ok);
}

bool pack_lines(struct Parser *p)
{
  return sphere_line_run(p) == 0;
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
