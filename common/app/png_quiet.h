/* libpng's error and warning handlers for the PNG writers (common/app/image.c
 * and the speed pack's bands): an error comes back as a longjmp to the
 * writer's setjmp, without libpng's own "libpng error: ..." line, so that
 * image_save says what failed and why; warnings are dropped. */
#ifndef RT_PNG_QUIET_H
#define RT_PNG_QUIET_H

#include <png.h>

static inline void png_quiet_error(png_structp png, png_const_charp message)
{
  (void)message;
  png_longjmp(png, 1);
}

static inline void png_quiet_warning(png_structp png, png_const_charp message)
{
  (void)png;
  (void)message;
}

#endif
