/* Antialiasing (step 07): the pixel as the mean colour over its square (a box
 * filter), from samples of the scene's pattern or, adaptively, from its
 * corners, cut in four where they differ. docs/07-antialiasing.md. */
#ifndef RT_ANTIALIAS_H
#define RT_ANTIALIAS_H

#include "vec.h"

typedef struct Scene Scene; /* scene.h */
typedef struct Film Film;   /* film.h */

/* The box filter: the colour of pixel (i, j) as the mean over its square.
 * With scene->sampler.adaptive T > 0, from its corners (each shared with the
 * neighbours) and centre, the square cut in four wherever they differ by
 * more than T, down to squares of side 2/sqrt(samples) (so the closest
 * samples are 1/sqrt(samples) apart, as in a sqrt(samples) x sqrt(samples)
 * grid); with T = 0, the mean of scene->samples samples of the scene's
 * pattern (scene->sampler.kind, keyed by its seed and the pixel). */
vec3s antialias_pixel(const Scene *scene, const Film *film, int i, int j);

#endif
