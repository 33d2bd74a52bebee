/* A text's lines parsed as a part of their own, and parts joined in file
 * order into the scene the one-pass parse makes (app/parser.h). The
 * statements are the one-pass parser's (parser_state.c); what a part cannot
 * know alone (a material another part defines, a once-statement another
 * part holds) is settled by the join. docs/performance.md. */
#include "app/parser.h"
#include "app/parser_state.h"

#include <stdlib.h>
#include <string.h>

#include "shapes.h"

struct ParserPart {
  Scene scene; /* instances: the caller's room */
  Parser p;
  int known;   /* the materials it was given: scene.materials[0 .. known) */
};

ParserPart *parser_part_parse(const char *file, const char *text, size_t from, size_t to,
                              const ParserPart *given, Instance *room, int n_room)
{
  /* aligned: a Scene holds cglm matrices, 32-byte aligned in AVX builds */
  size_t align = _Alignof(ParserPart);
  ParserPart *part = aligned_alloc(align, (sizeof *part + align - 1) / align * align);
  if (!part)
    return NULL;
  scene_init(&part->scene);
  part->scene.instances = room;
  parser_begin(&part->p, file, text + from, to - from, &part->scene);
  part->p.room = n_room > 0 ? n_room : -1; /* -1: no room, not the growing array */
  part->p.lx.quiet = true;
  part->known = 0;
  if (from == 0)
    lexer_skip_bom(&part->p.lx);
  bool ok = true;
  for (int k = 0; ok && given && k < given->scene.n_materials; k++)
    ok = scene_add_material(&part->scene, &given->scene.materials[k]) &&
         names_add(&part->p.names, parser_materials(&part->scene), k);
  part->known = part->scene.n_materials;
  if (ok && parser_statements(&part->p))
    return part;
  parser_part_free(part);
  return NULL;
}

int parser_part_shapes(const ParserPart *part)
{
  return part->scene.n_instances;
}

void parser_part_free(ParserPart *part)
{
  if (!part)
    return;
  parser_end(&part->p);
  part->scene.instances = NULL; /* the caller's room */
  scene_free(&part->scene);
  free(part);
}

/* Part q's once-statements into the joined scene; false when the scene
 * has one of them already. */
static bool join_once(Parser *j, const ParserPart *q)
{
  Scene *s = j->scene;
  const Scene *qs = &q->scene;
  for (int w = 0; w < ONCE_COUNT; w++) {
    if (!q->p.once_line[w])
      continue;
    if (j->once_line[w])
      return false;
    j->once_line[w] = q->p.once_line[w];
    switch (w) {
    case ONCE_FILM: s->width = qs->width, s->height = qs->height; break;
    case ONCE_CAMERA: s->camera = qs->camera; break;
    case ONCE_AMBIENT: s->ambient = qs->ambient; break;
    case ONCE_BACKGROUND: s->background = qs->background; break;
    case ONCE_SAMPLES: s->samples = qs->samples; break;
    default: s->light_samples = qs->light_samples; break;
    }
  }
  return true;
}

/* Part q's references to materials it had not seen, its instances now at
 * inst: those the joined scene defines by now get their material, the rest
 * wait for the joined parser's resolve. False when out of memory. */
static bool join_pending(Parser *j, const ParserPart *q, Instance *inst, int first)
{
  if (q->p.n_pending == 0)
    return true;
  int *found = malloc((size_t)q->p.n_forward * sizeof *found);
  if (!found)
    return false;
  for (int k = 0; k < q->p.n_forward; k++) /* each name looked up once */
    found[k] = names_find(&j->names, parser_materials(j->scene), q->p.forward[k].name,
                          (int)strlen(q->p.forward[k].name));
  bool ok = true;
  for (int k = 0; ok && k < q->p.n_pending; k++) {
    Pending r = q->p.pending[k];
    const char *name = q->p.forward[r.name].name;
    if (found[r.name] >= 0)
      inst[r.instance].material = found[r.name];
    else
      ok = parser_pending_add(j, first + r.instance, r.line, r.col, name, (int)strlen(name));
  }
  free(found);
  return ok;
}

/* Append part q to the joined scene: its once-statements, the materials it
 * defined itself (each name new), its lights, its instances moved down to
 * follow the scene's (their materials' indices moved past the scene's), its
 * references to materials it had not seen. False on a conflict or out of
 * memory. */
static bool join_part(Parser *j, const ParserPart *q)
{
  Scene *s = j->scene;
  const Scene *qs = &q->scene;
  int first_material = s->n_materials, first = s->n_instances, n = qs->n_instances;
  if (!join_once(j, q))
    return false;
  for (int k = q->known; k < qs->n_materials; k++) {
    const Material *m = &qs->materials[k];
    if (names_find(&j->names, parser_materials(s), m->name, (int)strlen(m->name)) >= 0 ||
        !scene_add_material(s, m) ||
        !names_add(&j->names, parser_materials(s), s->n_materials - 1))
      return false;
  }
  for (int k = 0; k < qs->n_lights; k++)
    if (!scene_add_light(s, &qs->lights[k]))
      return false;
  Instance *to = s->instances + first;
  if (n > 0 && to != qs->instances) /* the lines before held more than shapes */
    memmove(to, qs->instances, (size_t)n * sizeof *to);
  /* Given materials keep their index (the first part's, first in the
   * scene); the part's own follow the scene's. */
  int shift = first_material - q->known;
  if (shift != 0 && qs->n_materials > q->known)
    for (int k = 0; k < n; k++)
      to[k].material += to[k].material >= q->known ? shift : 0;
  s->n_instances += n;
  s->n_shapes = s->n_instances;
  return join_pending(j, q, to, first);
}

bool parser_parts_join(ParserPart *const *parts, int n, Instance *instances, Scene *scene)
{
  Scene s = *scene;
  s.instances = instances;
  Parser j;
  parser_begin(&j, n > 0 ? parts[0]->p.lx.file : "", "", 0, &s);
  j.lx.quiet = true;
  bool ok = true;
  for (int k = 0; ok && k < n; k++)
    ok = join_part(&j, parts[k]);
  ok = ok && parser_resolve(&j);
  parser_end(&j);
  s.instances = ok ? s.instances : NULL; /* the caller's on failure */
  if (!ok) {
    scene_free(&s);
    return false;
  }
  *scene = s;
  return true;
}
