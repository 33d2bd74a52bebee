/* A scene text parsed with stderr captured, for the tests of the parser's
 * messages: whether it parsed, and what it printed (at most size - 1 bytes,
 * NUL-terminated). The scene is freed either way. */
#ifndef RT_TEST_PARSE_CAPTURE_H
#define RT_TEST_PARSE_CAPTURE_H

#include <criterion/criterion.h>
#include <stdbool.h>
#include <stdio.h>

#include "app/parser.h"
#include "capture.h"

static inline bool parse_captured(const char *text, size_t len, char *msg, size_t size)
{
  FILE *tmp = tmpfile();
  cr_assert(tmp, "tmpfile failed");
  capture_begin(tmp);
  Scene s;
  scene_init(&s);
  bool ok = parser_load_text("t.scene", text, len, &s);
  capture_end();
  scene_free(&s);
  rewind(tmp);
  msg[fread(msg, 1, size - 1, tmp)] = '\0';
  fclose(tmp);
  return ok;
}

#endif
