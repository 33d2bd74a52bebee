/* Scene-file parser: the statements of docs/scene-format.md, checked as they
 * are read, against the limits that keep every later float finite. Materials
 * are found through a hash table; a material may be defined after its first
 * use (those references are resolved at the end). Introduced in step 02. */
#include "app/parser_state.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "film.h"
#include "grow.h"
#include "app/limits.h"
#include "app/light_statement.h"
#include "app/number.h"
#include "app/pack.h"

NameRecords parser_materials(const Scene *scene)
{
  return (NameRecords){scene->materials ? scene->materials[0].name : "", sizeof(Material)};
}

static NameRecords materials(const Parser *p)
{
  return parser_materials(p->scene);
}

static bool once(Parser *p, int which, const char *word)
{
  if (p->once_line[which])
    return lexer_fail(&p->lx, p->lx.tok[0].col, "expected one '%s' statement, found a "
                      "second (first at line %d)", word, p->once_line[which]);
  p->once_line[which] = p->lx.line;
  return true;
}

static bool st_film(Parser *p)
{
  int w, h, col = p->lx.tok[1 < p->lx.n ? 1 : 0].col;
  if (!once(p, ONCE_FILM, "film") ||
      !lexer_int(&p->lx, "the film width", 1, FILM_MAX_SIDE, &w) ||
      !lexer_int(&p->lx, "the film height", 1, FILM_MAX_SIDE, &h) ||
      !lexer_expect_end(&p->lx))
    return false;
  if ((long long)w * h > FILM_MAX_PIXELS)
    return lexer_fail(&p->lx, col, "expected at most %d pixels, found %dx%d",
                      FILM_MAX_PIXELS, w, h);
  p->scene->width = w;
  p->scene->height = h;
  return true;
}

/* `ambient` (a light: at most LEXER_MAX_COLOR, as a colour) or `background`
 * (seen as it is: any finite value >= 0). */
static bool st_colour(Parser *p, int which, const char *word, vec3s *out)
{
  char what[64];
  snprintf(what, sizeof what, "3 numbers >= 0 after '%s'", word);
  return once(p, which, word) &&
         lexer_colour(&p->lx, what, which == ONCE_AMBIENT ? LEXER_MAX_COLOR : INFINITY, out) &&
         lexer_expect_end(&p->lx);
}

static bool st_count(Parser *p, int which, const char *word, int *out)
{
  return once(p, which, word) &&
         lexer_int(&p->lx, which == ONCE_SAMPLES ? "the number of samples"
                   : "the number of light samples", 1, SCENE_MAX_SAMPLES, out) &&
         lexer_expect_end(&p->lx);
}

static bool st_camera(Parser *p)
{
  static const Key keys[] = {{"eye", KEY_POINT, false}, {"center", KEY_POINT, false},
                             {"up", KEY_VEC, false}, {"fov", KEY_NUM, false},
                             {"focal", KEY_NUM, false}};
  Field f[5];
  char text[LEXER_TOKEN_MAX];
  if (!once(p, ONCE_CAMERA, "camera") || !fields_read(&p->lx, "camera", keys, 5, f))
    return false;
  Camera *cam = &p->scene->camera;
  vec3s eye = f[0].set ? f[0].v : cam->eye, center = f[1].set ? f[1].v : cam->center;
  vec3s up = f[2].set ? f[2].v : cam->up;
  float fov = f[3].set ? f[3].v.x : cam->fov_y_deg, focal = f[4].set ? f[4].v.x : cam->focal;
  int col = f[1].set ? f[1].val_col : f[0].set ? f[0].val_col : p->lx.tok[0].col;
  if (glms_vec3_eqv(eye, center))
    return lexer_fail(&p->lx, col, "expected eye and center at different points, "
                      "found both at (%g %g %g)", eye.x, eye.y, eye.z);
  if (f[2].set && !limits_direction(&p->lx, &f[2], "up vector"))
    return false;
  if (!(limits_sin_angle(up, glms_vec3_sub(center, eye)) > 1e-6))
    return lexer_fail(&p->lx, f[2].set ? f[2].val_col : col, "expected an up vector "
                      "not parallel to the view direction, found up (%g %g %g)",
                      up.x, up.y, up.z);
  if (!(fov > 0.0f && fov < 180.0f))
    return lexer_fail(&p->lx, f[3].val_col, "expected a field of view in (0, 180) "
                      "degrees, found '%s'", fields_text(&p->lx, &f[3], 1, text, sizeof text));
  if (!(focal > 0.0f))
    return lexer_fail(&p->lx, f[4].val_col, "expected a focal distance > 0, found '%s'",
                      fields_text(&p->lx, &f[4], 1, text, sizeof text));
  if (focal < 1e-6f || focal > 1e6f)
    return lexer_fail(&p->lx, f[4].val_col, "expected a focal distance from 1e-6 to 1e6 "
                      "(the rays must stay finite in float), found '%s'",
                      fields_text(&p->lx, &f[4], 1, text, sizeof text));
  camera_init(cam, eye, center, up, fov, focal, cam->aspect);
  return true;
}

static bool st_material(Parser *p)
{
  static const Key keys[] = {{"ambient", KEY_COLOR, false}, {"diffuse", KEY_COLOR, false},
                             {"specular", KEY_COLOR, false}, {"shininess", KEY_NUM, false}};
  Material m = {.name = ""};
  Field f[4];
  Token name;
  char text[LEXER_TOKEN_MAX];
  if (!lexer_name(&p->lx, "a material name", MATERIAL_NAME_MAX - 1, &name))
    return false;
  if (names_find(&p->names, materials(p), name.s, name.len) >= 0)
    return lexer_fail(&p->lx, name.col, "expected a new material name, found '%.*s' "
                      "(already defined)", name.len, name.s);
  if (!fields_read(&p->lx, "material", keys, 4, f))
    return false;
  if (f[3].set && f[3].v.x < 0.0f)
    return lexer_fail(&p->lx, f[3].val_col, "expected shininess >= 0, found '%s'",
                      fields_text(&p->lx, &f[3], 1, text, sizeof text));
  memcpy(m.name, name.s, (size_t)name.len);
  m.diffuse = f[1].v;
  m.ambient = f[0].set ? f[0].v : m.diffuse; /* the documented default */
  m.specular = f[2].v;
  m.shininess = f[3].v.x;
  return scene_add_material(p->scene, &m) &&
         names_add(&p->names, materials(p), p->scene->n_materials - 1);
}

static NameRecords forward_records(const Parser *p)
{
  return (NameRecords){p->forward ? p->forward[0].name : "", sizeof(ForwardName)};
}

/* Room for n more pending references (common/grow.h); false when out of
 * memory. */
static bool pending_reserve(Parser *p, int n)
{
  if (grow_reserve((void **)&p->pending, (size_t)p->n_pending, (size_t)n, sizeof *p->pending))
    return true;
  fprintf(stderr, "parser: out of memory\n");
  return false;
}

/* The index in p->forward of `name`, added when new; -1 when out of memory. */
static int forward_name(Parser *p, const char *name, int len)
{
  int id = names_find(&p->forward_names, forward_records(p), name, len);
  if (id >= 0)
    return id;
  if (!grow_reserve((void **)&p->forward, (size_t)p->n_forward, 1, sizeof *p->forward)) {
    fprintf(stderr, "parser: out of memory\n");
    return -1;
  }
  ForwardName *f = &p->forward[p->n_forward];
  memcpy(f->name, name, (size_t)len);
  f->name[len] = '\0';
  if (!names_add(&p->forward_names, forward_records(p), p->n_forward))
    return -1;
  return p->n_forward++;
}

bool parser_pending_add(Parser *p, int instance, int line, int col, const char *name, int len)
{
  int id = forward_name(p, name, len);
  if (id < 0 || !pending_reserve(p, 1))
    return false;
  p->pending[p->n_pending++] = (Pending){instance, line, col, id};
  return true;
}

bool parser_place_shape(Parser *p, Instance *inst, const Token *name)
{
  Scene *s = p->scene;
  inst->light = -1;
  if (inst->material < 0) {
    inst->material = 0;
    if (!parser_pending_add(p, s->n_instances, p->lx.line, name->col, name->s, name->len))
      return false;
  }
  if (p->room == 0)
    return scene_add_instance(s, inst);
  if (s->n_instances >= p->room) /* room -1: a part given none */
    return false;
  s->instances[s->n_instances++] = *inst;
  s->n_shapes = s->n_instances;
  return true;
}

/* place_shape, the material looked up by its name. */
static bool add_shape(Parser *p, Instance *inst, const Token *name)
{
  inst->material = names_find(&p->names, materials(p), name->s, name->len);
  return parser_place_shape(p, inst, name);
}

static bool st_sphere(Parser *p)
{
  static const Key keys[] = {{"center", KEY_POINT, true}, {"radius", KEY_NUM, true},
                             {"material", KEY_NAME, true}};
  Field f[3];
  if (!fields_read(&p->lx, "sphere", keys, 3, f) || !limits_length(&p->lx, &f[1], "radius"))
    return false;
  Instance inst = {.shape = SHAPE_SPHERE, .sphere = {.center = f[0].v, .radius = f[1].v.x}};
  return add_shape(p, &inst, &p->lx.tok[f[2].val]);
}

static bool st_plane(Parser *p)
{
  static const Key keys[] = {{"point", KEY_POINT, true}, {"normal", KEY_VEC, true},
                             {"material", KEY_NAME, true}};
  Field f[3];
  if (!fields_read(&p->lx, "plane", keys, 3, f) || !limits_direction(&p->lx, &f[1], "normal"))
    return false;
  Plane plane = plane_make(f[0].v, f[1].v);
  Instance inst = {.shape = SHAPE_PLANE, .plane = plane};
  return add_shape(p, &inst, &p->lx.tok[f[2].val]);
}

static bool st_disc(Parser *p)
{
  static const Key keys[] = {{"center", KEY_POINT, true}, {"normal", KEY_VEC, true},
                             {"radius", KEY_NUM, true}, {"material", KEY_NAME, true}};
  Field f[4];
  if (!fields_read(&p->lx, "disc", keys, 4, f) || !limits_direction(&p->lx, &f[1], "normal") ||
      !limits_length(&p->lx, &f[2], "radius"))
    return false;
  Disc disc = disc_make(f[0].v, f[1].v, f[2].v.x);
  Instance inst = {.shape = SHAPE_DISC, .disc = disc};
  return add_shape(p, &inst, &p->lx.tok[f[3].val]);
}

static bool st_ambient(Parser *p)
{
  return st_colour(p, ONCE_AMBIENT, "ambient", &p->scene->ambient);
}

static bool st_background(Parser *p)
{
  return st_colour(p, ONCE_BACKGROUND, "background", &p->scene->background);
}

static bool st_light(Parser *p)
{
  Light light;
  return light_statement(&p->lx, &light) && scene_add_light(p->scene, &light);
}

static bool st_samples(Parser *p)
{
  return st_count(p, ONCE_SAMPLES, "samples", &p->scene->samples);
}

static bool st_light_samples(Parser *p)
{
  return st_count(p, ONCE_LIGHT_SAMPLES, "light_samples", &p->scene->light_samples);
}

/* The statement table: the statements by their first word, in the order an
 * unknown word's message lists them (docs/scene-format.md, "Statements");
 * each reads the rest of its line. The example is a valid line of it (a
 * shape's names the material `m`): tests/test_large_scene.c writes it into
 * its scene text; `once` marks the statements a file may hold once. The
 * lists of statements in the expected messages (the .err files of tests/bad/scenes,
 * tests/statements.h) and the fuzzing dictionary are generated from this
 * table by tools/figures/statements.sh (make regen-statements). */
static const struct Statement {
  const char *word;
  bool (*read)(Parser *p);
  const char *example;
  bool once;
} STATEMENTS[] = {
    {"film", st_film, "film 320 240", true},
    {"camera", st_camera, "camera eye 0 2 8 center 0 0.5 0 up 0 1 0 fov 50 focal 2", true},
    {"ambient", st_ambient, "ambient 0.1 0.2 0.3", true},
    {"background", st_background, "background 0.3 0.2 0.1", true},
    {"material", st_material,
     "material m diffuse 0.5 0.25 0.125 specular 0.1 0.2 0.3 shininess 8", false},
    {"plane", st_plane, "plane point 0 -1 0 normal 0 1 0.5 material m", false},
    {"sphere", st_sphere, "sphere center 0.5 1 -2 radius 0.5 material m", false},
    {"disc", st_disc, "disc center 0.25 2 -3 normal 1 1 0 radius 0.25 material m", false},
    {"light", st_light, "light point position 1 5 1 power 10 20 30 radius 0.5", false},
    {"samples", st_samples, "samples 9", true},
    {"light_samples", st_light_samples, "light_samples 4", true},
};
enum { STATEMENT_COUNT = sizeof STATEMENTS / sizeof *STATEMENTS };

int parser_statement_count(void)
{
  return STATEMENT_COUNT;
}

const char *parser_statement_word(int k)
{
  return STATEMENTS[k].word;
}

const char *parser_statement_example(int k)
{
  return STATEMENTS[k].example;
}

bool parser_statement_once(int k)
{
  return STATEMENTS[k].once;
}

static bool statement(Parser *p)
{
  Lexer *lx = &p->lx;
  for (int k = 0; k < STATEMENT_COUNT; k++)
    if (lexer_is(&lx->tok[0], STATEMENTS[k].word)) {
      lx->pos++;
      return STATEMENTS[k].read(p);
    }
  const char *words[STATEMENT_COUNT];
  for (int k = 0; k < STATEMENT_COUNT; k++)
    words[k] = STATEMENTS[k].word;
  return lexer_fail_unknown(lx, "a statement", words, STATEMENT_COUNT);
}

/* The references to materials defined after their use, in file order. */
bool parser_resolve(Parser *p)
{
  Scene *s = p->scene;
  int *found = malloc(((size_t)p->n_forward + 1) * sizeof *found);
  if (!found) {
    fprintf(stderr, "parser: out of memory\n");
    return false;
  }
  for (int k = 0; k < p->n_forward; k++) /* each name looked up once */
    found[k] = names_find(&p->names, materials(p), p->forward[k].name,
                          (int)strlen(p->forward[k].name));
  int k = 0;
  for (; k < p->n_pending && found[p->pending[k].name] >= 0; k++)
    s->instances[p->pending[k].instance].material = found[p->pending[k].name];
  free(found);
  if (k == p->n_pending)
    return true;
  /* Point the lexer back at the first undefined reference for the message. */
  const Pending *r = &p->pending[k];
  const char *name = p->forward[r->name].name;
  p->lx.line = r->line;
  p->lx.tok[0] = (Token){name, (int)strlen(name), r->col};
  p->lx.n = 1;
  p->lx.pos = 0;
  if (s->n_materials == 0)
    return lexer_fail(&p->lx, r->col, "expected a defined material name, found "
                      "'%s' (the file defines no material)", name);
  const char *names[64];
  int n_names = s->n_materials < 64 ? s->n_materials : 64;
  for (int j = 0; j < n_names; j++)
    names[j] = s->materials[j].name;
  return lexer_fail_unknown(&p->lx, "a defined material name", names, n_names);
}

void parser_begin(Parser *p, const char *file, const char *text, size_t len, Scene *scene)
{
  *p = (Parser){.scene = scene};
  names_init(&p->names);
  names_init(&p->forward_names);
  lexer_init(&p->lx, file, text, len);
}

/* A material name found in a run of sphere lines, and its material. */
typedef struct RecentName {
  const char *name;
  int len, material;
} RecentName;

enum { RECENT_NAMES = 8 };

/* The material a sphere line names: one of the last RECENT_NAMES names
 * found in this run of lines (a material's index never changes while a
 * text is parsed), else names_find after lexer_name_valid; -2 when the name
 * is not a valid one. */
static int line_material(Parser *p, RecentName *recent, unsigned *n_recent,
                         const PackSphereLine *sl)
{
  unsigned n = *n_recent < RECENT_NAMES ? *n_recent : RECENT_NAMES;
  for (unsigned k = 0; k < n; k++)
    if (recent[k].len == sl->name_len && memcmp(recent[k].name, sl->name, (size_t)sl->name_len) == 0)
      return recent[k].material;
  if (!lexer_name_valid(sl->name, sl->name_len, MATERIAL_NAME_MAX - 1))
    return -2;
  int material = names_find(&p->names, parser_materials(p->scene), sl->name, sl->name_len);
  recent[(*n_recent)++ % RECENT_NAMES] = (RecentName){sl->name, sl->name_len, material};
  return material;
}

/* The sphere lines that follow, as the speed pack reads them straight from
 * the text (pack_sphere_line): each value checked as st_sphere's fields
 * check it; the first line the pack declines, or any value in doubt, is
 * left to the general path (lexer_line, statement), which reads it and says
 * what is wrong. False when out of memory. */
static bool sphere_lines(Parser *p)
{
  Lexer *lx = &p->lx;
  PackSphereLine sl;
  RecentName recent[RECENT_NAMES];
  unsigned n_recent = 0;
  while (pack_sphere_line(lx->next, lx->end, &sl)) {
    if (sl.longest >= LEXER_TOKEN_MAX || !fields_coordinate_ok(sl.v[0]) ||
        !fields_coordinate_ok(sl.v[1]) || !fields_coordinate_ok(sl.v[2]) ||
        !limits_length_ok(sl.v[3]))
      return true;
    int material = line_material(p, recent, &n_recent, &sl);
    if (material == -2)
      return true;
    Token tok = {sl.name, sl.name_len, (int)(sl.name - lx->next) + 1};
    lx->line++;
    lx->n = lx->pos = 0;
    lx->next = sl.next;
    Instance inst = {.shape = SHAPE_SPHERE,
                     .sphere = {.center = {{sl.v[0], sl.v[1], sl.v[2]}}, .radius = sl.v[3]},
                     .material = material};
    if (!parser_place_shape(p, &inst, &tok))
      return false;
  }
  return true;
}

bool parser_statements(Parser *p)
{
  for (;;) {
    if (!sphere_lines(p))
      return false;
    int more = lexer_line(&p->lx);
    if (more == 0)
      return true;
    if (more < 0 || !statement(p))
      return false;
  }
}

void parser_end(Parser *p)
{
  free(p->pending);
  free(p->forward);
  names_free(&p->names);
  names_free(&p->forward_names);
  p->pending = NULL;
  p->forward = NULL;
  p->n_pending = p->n_forward = 0;
}
