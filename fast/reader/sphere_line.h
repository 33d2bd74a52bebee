/* The line a large scene is made of, `sphere center X Y Z radius R material
 * NAME`, read straight from the text instead of word by word
 * (pack_sphere_line, app/pack.h). */
#ifndef RT_SPHERE_LINE_H
#define RT_SPHERE_LINE_H

#include <stdbool.h>

#include "app/pack.h"

/* pack_sphere_line: true, *out filled, when the line at `line` is such a
 * line, each number a plain decimal (decimal_prefix) read as the scene
 * format's number reader reads it; false otherwise. */
bool sphere_line_read(const char *line, const char *end, PackSphereLine *out);

/* Whether sphere_line_read reads anything (true). The tests turn it off to
 * compare with the general path. */
extern bool sphere_line_on;

#endif
