/* Whole scene texts (step 02): a file read whole, then parsed statement by
 * statement (common/app/parser_state.c), or, when the speed pack takes a
 * large text, in parts at once (pack_parse, common/app/parser_part.c).
 * docs/scene-format.md. */
#include "app/parser.h"
#include "app/parser_state.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "app/pack.h"
#include "app/textfile.h"

bool parser_load_whole(const char *file, const char *text, size_t len, Scene *scene)
{
  Parser p;
  parser_begin(&p, file, text, len, scene);
  lexer_skip_bom(&p.lx);
  bool ok = parser_statements(&p) && parser_resolve(&p);
  parser_end(&p);
  if (!ok)
    scene_free(scene);
  return ok;
}

bool parser_load_text(const char *file, const char *text, size_t len, Scene *scene)
{
  if (len > PARSER_MAX_BYTES) {
    fprintf(stderr, "%s: expected at most %zu bytes, found %zu\n", file,
            PARSER_MAX_BYTES, len);
    scene_free(scene);
    return false;
  }
  return pack_parse(file, text, len, scene) || parser_load_whole(file, text, len, scene);
}

bool parser_load_string(const char *file, const char *text, Scene *scene)
{
  return parser_load_text(file, text, strlen(text), scene);
}

bool parser_load_file(const char *path, Scene *scene)
{
  TextFile f;
  int err = textfile_read(path, PARSER_MAX_BYTES, &f);
  if (err == EFBIG)
    fprintf(stderr, "parser: cannot read '%s': larger than %zu bytes, the limit of a "
            "scene file\n", path, PARSER_MAX_BYTES);
  else if (err)
    fprintf(stderr, "parser: cannot read '%s': %s\n", path, strerror(err));
  if (err) {
    scene_free(scene);
    return false;
  }
  bool ok = parser_load_text(path, f.text, f.len, scene);
  textfile_free(&f);
  return ok;
}
