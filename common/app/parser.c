/* Scene-file parser: the statements of docs/scene-format.md, checked as they
 * are read; material names are resolved at the end, so a material may be
 * defined after its first use. Introduced in step 02. */
#include "app/parser.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "film.h"
#include "app/lexer.h"

/* Statements that may appear once per file. */
enum { ONCE_FILM, ONCE_CAMERA, ONCE_AMBIENT, ONCE_BACKGROUND, ONCE_SAMPLES,
       ONCE_LIGHT_SAMPLES, ONCE_COUNT };

typedef struct MaterialRef {
  int line, col;
  char name[MATERIAL_NAME_MAX];
} MaterialRef;

typedef struct Parser {
  Lexer lx;
  Scene *scene;
  MaterialRef *refs; /* one per instance, in order */
  int n_refs;
  int once_line[ONCE_COUNT];
} Parser;

static bool once(Parser *p, int which, const char *word)
{
  if (p->once_line[which])
    return lexer_fail(&p->lx, 1, "expected one '%s' statement, found a second "
                      "(first at line %d)", word, p->once_line[which]);
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

static bool st_colour(Parser *p, int which, const char *word, vec3s *out)
{
  char what[64];
  snprintf(what, sizeof what, "3 numbers >= 0 after '%s'", word);
  return once(p, which, word) && lexer_vec(&p->lx, what, true, out) &&
         lexer_expect_end(&p->lx);
}

static bool st_count(Parser *p, int which, const char *word, int *out)
{
  return once(p, which, word) &&
         lexer_int(&p->lx, which == ONCE_SAMPLES ? "the number of samples"
                   : "the number of light samples", 1, SCENE_MAX_SAMPLES, out) &&
         lexer_expect_end(&p->lx);
}

/* sin of the angle between a and b, in double. */
static double sin_angle(vec3s a, vec3s b)
{
  double cx = (double)a.y * b.z - (double)a.z * b.y;
  double cy = (double)a.z * b.x - (double)a.x * b.z;
  double cz = (double)a.x * b.y - (double)a.y * b.x;
  double la = (double)a.x * a.x + (double)a.y * a.y + (double)a.z * a.z;
  double lb = (double)b.x * b.x + (double)b.y * b.y + (double)b.z * b.z;
  return sqrt((cx * cx + cy * cy + cz * cz) / (la * lb));
}

static bool st_camera(Parser *p)
{
  static const Key keys[] = {{"eye", KEY_VEC, false}, {"center", KEY_VEC, false},
                             {"up", KEY_VEC, false}, {"fov", KEY_NUM, false},
                             {"focal", KEY_NUM, false}};
  Field f[5];
  if (!once(p, ONCE_CAMERA, "camera") || !lexer_fields(&p->lx, "camera", keys, 5, f))
    return false;
  Camera *cam = &p->scene->camera;
  vec3s eye = f[0].set ? f[0].v : cam->eye, center = f[1].set ? f[1].v : cam->center;
  vec3s up = f[2].set ? f[2].v : cam->up;
  float fov = f[3].set ? f[3].v.x : cam->fov_y_deg, focal = f[4].set ? f[4].v.x : cam->focal;
  int col = f[1].set ? f[1].val_col : f[0].set ? f[0].val_col : 1;
  if (glms_vec3_eqv(eye, center))
    return lexer_fail(&p->lx, col, "expected eye and center at different points, "
                      "found both at (%g %g %g)", eye.x, eye.y, eye.z);
  if (vec_is_zero(up))
    return lexer_fail(&p->lx, f[2].val_col, "expected a non-zero up vector, found '0 0 0'");
  if (!(sin_angle(up, glms_vec3_sub(center, eye)) > 1e-6))
    return lexer_fail(&p->lx, f[2].set ? f[2].val_col : col, "expected an up vector "
                      "not parallel to the view direction, found up (%g %g %g)",
                      up.x, up.y, up.z);
  if (!(fov > 0.0f && fov < 180.0f))
    return lexer_fail(&p->lx, f[3].val_col, "expected a field of view in (0, 180) "
                      "degrees, found '%s'", f[3].text);
  if (!(focal > 0.0f))
    return lexer_fail(&p->lx, f[4].val_col, "expected a focal distance > 0, found '%s'",
                      f[4].text);
  camera_init(cam, eye, center, up, fov, focal, cam->aspect);
  return true;
}

static bool st_material(Parser *p)
{
  static const Key keys[] = {{"ambient", KEY_COLOR, false}, {"diffuse", KEY_COLOR, false},
                             {"specular", KEY_COLOR, false}, {"shininess", KEY_NUM, false}};
  Material m = {.name = ""};
  Field f[4];
  int col = p->lx.pos < p->lx.n ? p->lx.tok[p->lx.pos].col : p->lx.end_col;
  if (!lexer_name(&p->lx, "a material name", m.name))
    return false;
  int prev = scene_find_material(p->scene, m.name);
  if (prev >= 0)
    return lexer_fail(&p->lx, col, "expected a new material name, found '%s' "
                      "(already defined)", m.name);
  if (!lexer_fields(&p->lx, "material", keys, 4, f))
    return false;
  if (f[3].set && f[3].v.x < 0.0f)
    return lexer_fail(&p->lx, f[3].val_col, "expected shininess >= 0, found '%s'", f[3].text);
  m.diffuse = f[1].v;
  m.ambient = f[0].set ? f[0].v : m.diffuse; /* the documented default */
  m.specular = f[2].v;
  m.shininess = f[3].v.x;
  return scene_add_material(p->scene, &m);
}

/* Add a lit instance whose material is resolved at the end. */
static bool add_shape(Parser *p, Instance *inst, const Field *material)
{
  if ((p->n_refs & (p->n_refs - 1)) == 0) {
    MaterialRef *bigger = realloc(p->refs, sizeof *bigger * (size_t)(p->n_refs ? 2 * p->n_refs : 4));
    if (!bigger) {
      fprintf(stderr, "parser: out of memory\n");
      return false;
    }
    p->refs = bigger;
  }
  MaterialRef *ref = &p->refs[p->n_refs++];
  ref->line = p->lx.line;
  ref->col = material->val_col;
  memcpy(ref->name, material->name, sizeof ref->name);
  inst->material = 0; /* resolved in resolve_materials */
  inst->light = -1;
  return scene_add_instance(p->scene, inst);
}

static bool st_sphere(Parser *p)
{
  static const Key keys[] = {{"center", KEY_VEC, true}, {"radius", KEY_NUM, true},
                             {"material", KEY_NAME, true}};
  Field f[3];
  if (!lexer_fields(&p->lx, "sphere", keys, 3, f))
    return false;
  if (!(f[1].v.x > 0.0f))
    return lexer_fail(&p->lx, f[1].val_col, "expected a radius > 0, found '%s'", f[1].text);
  Instance inst = {.shape = SHAPE_SPHERE, .sphere = {.center = f[0].v, .radius = f[1].v.x}};
  return add_shape(p, &inst, &f[2]);
}

static bool st_plane(Parser *p)
{
  static const Key keys[] = {{"point", KEY_VEC, true}, {"normal", KEY_VEC, true},
                             {"material", KEY_NAME, true}};
  Field f[3];
  if (!lexer_fields(&p->lx, "plane", keys, 3, f))
    return false;
  if (vec_is_zero(f[1].v))
    return lexer_fail(&p->lx, f[1].val_col, "expected a non-zero normal, found '0 0 0'");
  Instance inst = {.shape = SHAPE_PLANE, .plane = plane_make(f[0].v, f[1].v)};
  return add_shape(p, &inst, &f[2]);
}

static bool st_light(Parser *p)
{
  static const char *const types[] = {"point", "directional", "area"};
  static const Key point[] = {{"position", KEY_VEC, true}, {"power", KEY_COLOR, true},
                              {"radius", KEY_NUM, false}};
  static const Key dir[] = {{"direction", KEY_VEC, true}, {"irradiance", KEY_COLOR, true}};
  static const Key area[] = {{"corner", KEY_VEC, true}, {"edge1", KEY_VEC, true},
                             {"edge2", KEY_VEC, true}, {"power", KEY_COLOR, true}};
  Lexer *lx = &p->lx;
  Light light = {.type = LIGHT_POINT};
  Field f[4];
  if (lexer_peek_is(lx, "point")) {
    lx->pos++;
    if (!lexer_fields(lx, "point light", point, 3, f))
      return false;
    if (f[2].set && !(f[2].v.x > 0.0f))
      return lexer_fail(lx, f[2].val_col, "expected a radius > 0, found '%s'", f[2].text);
    light.position = f[0].v;
    light.power = f[1].v;
    light.radius = f[2].v.x;
  } else if (lexer_peek_is(lx, "directional")) {
    lx->pos++;
    if (!lexer_fields(lx, "directional light", dir, 2, f))
      return false;
    if (vec_is_zero(f[0].v))
      return lexer_fail(lx, f[0].val_col, "expected a non-zero direction, found '0 0 0'");
    light.type = LIGHT_DIRECTIONAL;
    light.direction = glms_vec3_normalize(f[0].v);
    light.irradiance = f[1].v;
  } else if (lexer_peek_is(lx, "area")) {
    lx->pos++;
    if (!lexer_fields(lx, "area light", area, 4, f))
      return false;
    for (int k = 1; k <= 2; k++)
      if (vec_is_zero(f[k].v))
        return lexer_fail(lx, f[k].val_col, "expected a non-zero %s, found '0 0 0'",
                          k == 1 ? "edge1" : "edge2");
    if (!(sin_angle(f[1].v, f[2].v) > 1e-6))
      return lexer_fail(lx, f[2].val_col, "expected edge2 not parallel to edge1 "
                        "(a light with an area), found parallel edges");
    light.type = LIGHT_AREA;
    light.quad = quad_make(f[0].v, f[1].v, f[2].v);
    light.power = f[3].v;
  } else if (lx->pos < lx->n) {
    return lexer_fail_unknown(lx, "a light type", types, 3);
  } else {
    return lexer_fail(lx, lx->end_col, "expected a light type (point, directional, "
                      "area), found end of line");
  }
  return scene_add_light(p->scene, &light);
}

static bool statement(Parser *p)
{
  static const char *const words[] = {"film", "camera", "ambient", "background",
                                      "material", "plane", "sphere", "light",
                                      "samples", "light_samples"};
  Lexer *lx = &p->lx;
  Scene *s = p->scene;
  int k = 0;
  while (k < 10 && !lexer_peek_is(lx, words[k]))
    k++;
  if (k == 10)
    return lexer_fail_unknown(lx, "a statement", words, 10);
  lx->pos++;
  switch (k) {
  case 0: return st_film(p);
  case 1: return st_camera(p);
  case 2: return st_colour(p, ONCE_AMBIENT, "ambient", &s->ambient);
  case 3: return st_colour(p, ONCE_BACKGROUND, "background", &s->background);
  case 4: return st_material(p);
  case 5: return st_plane(p);
  case 6: return st_sphere(p);
  case 7: return st_light(p);
  case 8: return st_count(p, ONCE_SAMPLES, "samples", &s->samples);
  default: return st_count(p, ONCE_LIGHT_SAMPLES, "light_samples", &s->light_samples);
  }
}

static bool resolve_materials(Parser *p)
{
  Scene *s = p->scene;
  const char *names[64];
  int n_names = s->n_materials < 64 ? s->n_materials : 64;
  for (int k = 0; k < n_names; k++)
    names[k] = s->materials[k].name;
  for (int k = 0; k < p->n_refs; k++) {
    int m = scene_find_material(s, p->refs[k].name);
    if (m < 0) {
      /* Point the lexer back at the reference for the message. */
      Token t = {p->refs[k].name, (int)strlen(p->refs[k].name), p->refs[k].col};
      p->lx.line = p->refs[k].line;
      p->lx.tok[0] = t;
      p->lx.n = 1;
      p->lx.pos = 0;
      if (n_names == 0)
        return lexer_fail(&p->lx, t.col, "expected a defined material name, found "
                          "'%s' (the file defines no material)", t.s);
      return lexer_fail_unknown(&p->lx, "a defined material name", names, n_names);
    }
    s->instances[k].material = m;
  }
  return true;
}

bool parser_load_string(const char *file, const char *text, Scene *scene)
{
  Parser p = {.scene = scene};
  lexer_init(&p.lx, file, text);
  int more;
  bool ok = true;
  while (ok && (more = lexer_line(&p.lx)) != 0)
    ok = more > 0 && statement(&p);
  ok = ok && resolve_materials(&p);
  free(p.refs);
  if (!ok)
    scene_free(scene);
  return ok;
}

bool parser_load_file(const char *path, Scene *scene)
{
  FILE *f = fopen(path, "rb");
  char *text = NULL;
  size_t len = 0;
  if (f) {
    size_t cap = 0, got;
    do {
      if (len + 65536 + 1 > cap) {
        char *bigger = realloc(text, cap = 2 * cap + 65536 + 1);
        if (!bigger)
          break;
        text = bigger;
      }
      got = fread(text + len, 1, cap - len - 1, f);
      len += got;
    } while (got > 0);
  }
  if (!f || ferror(f) || !text) {
    fprintf(stderr, "parser: cannot read '%s': %s\n", path, strerror(f ? EIO : errno));
    if (f)
      fclose(f);
    free(text);
    return false;
  }
  fclose(f);
  text[len] = '\0';
  if (strlen(text) != len) {
    fprintf(stderr, "%s: expected a text file, found a NUL byte\n", path);
    free(text);
    return false;
  }
  bool ok = parser_load_string(path, text, scene);
  free(text);
  return ok;
}
