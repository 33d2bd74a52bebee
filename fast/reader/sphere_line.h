/* The line a large scene is made of, `sphere center X Y Z radius R material
 * NAME`, read straight from the text instead of word by word (pack_lines,
 * app/pack.h). */
#ifndef RT_SPHERE_LINE_H
#define RT_SPHERE_LINE_H

#include <stdbool.h>

#include "app/parser_state.h"

/* Read the sphere lines that follow in p's text, as parser_statements would
 * read them, up to the first other line (or any line of doubt), which the
 * general path then reads. 0 when done, -1 when out of memory. */
int sphere_line_run(Parser *p);

/* Whether sphere_line_run reads anything (true). The tests turn it off to
 * compare with the general path. */
extern bool sphere_line_on;

#endif
