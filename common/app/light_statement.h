/* The `light` statement of the scene format: a point, directional or area
 * light from the rest of its line. Introduced in step 04 (area lights in step
 * 08); docs/scene-format.md, "Statements". */
#ifndef RT_LIGHT_STATEMENT_H
#define RT_LIGHT_STATEMENT_H

#include "app/lexer.h"
#include "light.h"

/* Read the light type and its keywords (the word `light` already read) into
 * *light, the direction normalised and the area light's quad made. Prints
 * one FILE:LINE:COL line and returns false on error. */
bool light_statement(Lexer *lx, Light *light);

#endif
