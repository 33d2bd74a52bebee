/* Film: a w x h grid of linear float RGB pixels (step 01). Pixel (i, j) has i
 * from the left and j from the bottom; its centre sample is
 * ((i + 0.5)/w, (j + 0.5)/h). Bytes appear only at export. docs/01-film.md. */
#ifndef RT_FILM_H
#define RT_FILM_H

#include <stdbool.h>
#include "vec.h"

typedef enum Tonemap {
  TONEMAP_CLAMP,    /* byte = round(255 clamp(c, 0, 1)), the lecture's mapping */
  TONEMAP_SRGB,     /* clamp, then the sRGB transfer curve */
  TONEMAP_REINHARD, /* c / (1 + c), then sRGB */
} Tonemap;

typedef struct Film {
  int width, height;
  float *rgb; /* width * height * 3 floats, row j = 0 first; owned */
  struct RenderMemo *memo; /* adaptive sampling's colours traced so far in
                            * this tile (steps 07, 08; app/render_point.h):
                            * the render loop's, one per thread; NULL: none */
} Film;

/* Film limits the parser and command line enforce. */
enum { FILM_MAX_SIDE = 16384, FILM_MAX_PIXELS = 16777216 };

/* Allocate a black film. Prints one line and returns false when out of memory. */
bool film_init(Film *film, int width, int height);

/* Free the pixels; a second call is harmless. */
void film_free(Film *film);

/* The lecture's GetSample: normalized coordinates of pixel (i, j)'s centre. */
vec2s film_sample(const Film *film, int i, int j);

/* Set / get pixel (i, j). */
void film_set(Film *film, int i, int j, vec3s c);
vec3s film_get(const Film *film, int i, int j);

/* Export: the byte a linear value c maps to under `tm` (NaN and c <= 0 give
 * 0; TONEMAP_CLAMP gives round(255 clamp(c, 0, 1)), halves rounded up). The
 * image files (common/app/image.c) are written through it. */
unsigned char film_to_byte(float c, Tonemap tm);

/* Compensated (float-float, TwoSum) sum of colour samples: the mean of
 * millions of samples keeps float precision (docs/accuracy.md). */
typedef struct FilmAccum {
  vec3s sum, comp;
  unsigned n;
} FilmAccum;

void film_accum_add(FilmAccum *acc, vec3s c);
vec3s film_accum_mean(const FilmAccum *acc);

#endif
