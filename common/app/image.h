/* Image files and image comparison (step 01): atomic writes of PNG (libpng),
 * JPG and HDR (stb) and PFM (by hand), every byte from film_to_byte; loading;
 * per-pixel comparison. docs/01-film.md. Pixel buffers are RGB floats, rows from the bottom (j = 0)
 * like the film; files are written upright. */
#ifndef RT_IMAGE_H
#define RT_IMAGE_H

#include <stdbool.h>

#include "film.h"

/* Parse "clamp", "srgb" or "reinhard"; false when unknown. */
bool image_tonemap_parse(const char *name, Tonemap *out);

/* True when `path` ends in an extension image_save can write; otherwise
 * prints one line naming the path and the accepted extensions. */
bool image_format_known(const char *path);

/* Write w x h RGB floats to `path`, format from its extension (.png, .jpg,
 * .hdr, .pfm). The file is written to a temporary name and renamed, so an
 * existing file is replaced only by a complete one. .hdr and .pfm keep the
 * linear floats (no tone map). Prints one line and returns false on failure. */
bool image_save(const char *path, int w, int h, const float *rgb, Tonemap tm);

/* The writer of every picture the repository keeps (images/, docs/img/,
 * written by make regen through tools/loop/imgcmp.c): a .png through libpng
 * alone, whatever the build's speed pack, so that every kept picture comes
 * from one encoder. Clamped bytes; atomic like image_save. */
bool image_save_kept(const char *path, int w, int h, const float *rgb);

/* Load a .png (bytes / 255, no tone map undone) or .pfm (exact floats) into a
 * new buffer the caller frees with free(). Prints one line, false on failure. */
bool image_load(const char *path, int *w, int *h, float **rgb);

typedef struct ImageDiff {
  double rmse;        /* root mean square over all channels */
  float max_abs;      /* largest per-channel difference */
  long over;          /* channels whose difference exceeds the tolerance */
} ImageDiff;

/* Compare two same-size buffers channel by channel against `tol`. */
ImageDiff image_compare(int w, int h, const float *a, const float *b, float tol);

/* Write a diff picture: |a - b| scaled by `gain`, red where over `tol`. */
bool image_save_diff(const char *path, int w, int h, const float *a,
                     const float *b, float tol, float gain);

#endif
