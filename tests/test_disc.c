/* Tests of the disc (common/disc.c, given code) and of its `disc` statement:
 * hits at the closed-form distance, the rim, misses, parallel rays, back
 * faces, tilted discs against a long-double reference; the statement read
 * into the scene, its errors, the scene file scenes/disc.scene.
 * docs/scene-format.md, "Statements". */
#include "parse_capture.h"
#include "check.h"

#include <stdlib.h>

#include "app/parser.h"
#include "disc.h"
#include "scene.h"
#include "scene_index.h"

#define DOC "docs/scene-format.md, \"Statements\""

static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz)
{
  Ray r = {.o = vec_make(ox, oy, oz), .d = glms_vec3_normalize(vec_make(dx, dy, dz))};
  return r;
}

/* The unit disc in the plane z = 0, normal +z (given as (0, 0, 2)). */
static Disc unit_disc(void)
{
  return disc_make(vec_make(0, 0, 0), vec_make(0, 0, 2), 1.0f);
}

Test(disc, straight_hits_at_the_plane_distance)
{
  Disc d = unit_disc();
  Check ct = CHECK("disc_hit_t", DOC), f = CHECK("disc_hit_fill", DOC);
  CHECK_VEC(&f, vec_make(0, 0, 1), d.normal, 0.0, "disc_make: normal (0, 0, 2) stored unit");
  CHECK_NEAR(&ct, 5.0, disc_hit_t(&d, ray(0.5f, -0.25f, 5, 0, 0, -1), INFINITY), 0.0,
             "ray from (0.5, -0.25, 5) along -z to the unit disc at z = 0: t");
  CHECK_NEAR(&ct, 3.0, disc_hit_t(&d, ray(0, 0, -3, 0, 0, 1), INFINITY), 0.0,
             "ray from (0, 0, -3) along +z (from behind): t");
  Hit h;
  disc_hit_fill(&d, ray(0.5f, -0.25f, 5, 0, 0, -1), 5.0f, &h);
  CHECK_VEC(&f, vec_make(0.5f, -0.25f, 0), h.p, 0.0, "the ray from (0.5, -0.25, 5) at t = 5: hit.p");
  CHECK_VEC(&f, vec_make(0, 0, 1), h.n, 0.0, "the same ray, from the front: hit.n");
  CHECK_INT(&f, 0, h.backface, "the same ray, from the front: hit.backface");
  disc_hit_fill(&d, ray(0, 0, -3, 0, 0, 1), 3.0f, &h);
  CHECK_VEC(&f, vec_make(0, 0, -1), h.n, 0.0, "a ray from behind: hit.n faces it");
  CHECK_INT(&f, 1, h.backface, "a ray from behind: hit.backface");
  CHECK_DONE(&ct);
  CHECK_DONE(&f);
}

Test(disc, rim_counts_and_outside_misses)
{
  Disc d = unit_disc();
  Check c = CHECK("disc_hit_t", DOC);
  /* (1, 0) and (0.6, 0.8) are on the rim: 0.36f + 0.64f rounds to 1. */
  CHECK_NEAR(&c, 2.0, disc_hit_t(&d, ray(1, 0, 2, 0, 0, -1), INFINITY), 0.0,
             "ray along -z through (1, 0, 0), on the rim of the unit disc: t");
  CHECK_NEAR(&c, INFINITY, disc_hit_t(&d, ray(1.0001f, 0, 2, 0, 0, -1), INFINITY), 0.0,
             "ray along -z through (1.0001, 0, 0), just outside: a miss");
  CHECK_NEAR(&c, INFINITY, disc_hit_t(&d, ray(0.72f, 0.72f, 2, 0, 0, -1), INFINITY), 0.0,
             "ray along -z through (0.72, 0.72, 0), |p| = 1.018: a miss");
  CHECK_NEAR(&c, INFINITY, disc_hit_t(&d, ray(0, 0, 2, 1, 0, 0), INFINITY), 0.0,
             "ray parallel to the disc: a miss");
  CHECK_NEAR(&c, INFINITY, disc_hit_t(&d, ray(0, 0, 2, 0, 0, 1), INFINITY), 0.0,
             "ray from (0, 0, 2) away from the disc: a miss (t < 0)");
  CHECK_NEAR(&c, INFINITY, disc_hit_t(&d, ray(0, 0, 2, 0, 0, -1), 2.0f), 0.0,
             "ray from (0, 0, 2) toward it with tmax = 2 = t: a miss (t < tmax only)");
  CHECK_DONE(&c);
}

/* A tilted disc against the closed form in long double: t = (c - o).n /
 * (d.n) and |o + t d - c| <= r, for rays from a grid of origins through a
 * grid of points around the disc (rays within 1e-4 of the rim skipped: float
 * may decide either way there). */
Test(disc, tilted_agrees_with_the_closed_form)
{
  vec3s c = vec_make(1.0f, -2.0f, 0.5f), n = vec_make(1.0f, 2.0f, -2.0f);
  float radius = 1.5f;
  Disc d = disc_make(c, n, radius);
  long double nl[3] = {1.0L / 3, 2.0L / 3, -2.0L / 3};
  Check ck = CHECK("disc_hit_t", DOC);
  for (int k = 0; k < 400; k++) {
    vec3s o = vec_make(-4.0f + 0.37f * (float)(k % 7), 3.0f + 0.21f * (float)(k % 5),
                       -5.0f + 0.13f * (float)(k % 11));
    vec3s at = vec_make(c.x + 0.11f * (float)(k % 29 - 14), c.y + 0.07f * (float)(k % 31 - 15),
                        c.z + 0.05f * (float)(k % 23 - 11));
    Ray r = {.o = o, .d = glms_vec3_normalize(glms_vec3_sub(at, o))};
    long double dn = 0, cn = 0;
    for (int a = 0; a < 3; a++) {
      dn += (long double)r.d.raw[a] * nl[a];
      cn += ((long double)c.raw[a] - o.raw[a]) * nl[a];
    }
    long double t = cn / dn, dist2 = 0;
    for (int a = 0; a < 3; a++) {
      long double rel = (long double)o.raw[a] + t * r.d.raw[a] - c.raw[a];
      dist2 += rel * rel;
    }
    long double dist = sqrtl(dist2);
    if (fabsl(dist - radius) < 1e-4L * radius || !(t > 0))
      continue;
    float got = disc_hit_t(&d, r, INFINITY);
    if (dist < radius)
      CHECK_REL(&ck, (double)t, got, 1e-5, "ray %d from (%g, %g, %g) to the tilted disc, "
                "%.6Lg from its centre (radius 1.5): t", k, o.x, o.y, o.z, dist);
    else
      CHECK_NEAR(&ck, INFINITY, got, 0.0, "ray %d from (%g, %g, %g) to the tilted disc's "
                 "plane %.6Lg from its centre (radius 1.5): a miss", k, o.x, o.y, o.z, dist);
  }
  CHECK_DONE(&ck);
}

Test(disc, statement_into_the_scene)
{
  Scene s;
  scene_init(&s);
  Check c = CHECK("parser_load_string", DOC);
  cr_assert(parser_load_string("t.scene", "material m diffuse 1 1 1\n"
                               "disc radius 0.5 material m normal 0 3 0 center 1 2 3\n", &s),
            "parser_load_string refused a disc statement (its message is above)\n  read " DOC);
  CHECK_REQUIRE(&c, s.n_instances == 1 && s.instances[0].shape == SHAPE_DISC,
                "a disc statement: expected 1 instance of shape SHAPE_DISC (%d), got %d "
                "instance(s), the first of shape %d", SHAPE_DISC, s.n_instances,
                s.n_instances ? (int)s.instances[0].shape : -1);
  const Disc *d = &s.instances[0].disc;
  CHECK_VEC(&c, vec_make(1, 2, 3), d->center, 0.0, "disc center 1 2 3");
  CHECK_VEC(&c, vec_make(0, 1, 0), d->normal, 0.0, "disc normal 0 3 0: stored unit");
  CHECK_NEAR(&c, 0.5, d->radius, 0.0, "disc radius 0.5");
  CHECK_INT(&c, 0, s.instances[0].material, "disc material m: material 0");
  CHECK_THAT(&c, strcmp(scene_shape_name(SHAPE_DISC), "disc") == 0,
             "scene_shape_name(SHAPE_DISC): expected \"disc\" (the statement's word), got "
             "\"%s\"", scene_shape_name(SHAPE_DISC));
  CHECK_DONE(&c);
  scene_free(&s);
}

/* What parser_load_text prints for `text` (it must fail). */
static void expect_error(Check *c, const char *text, const char *message)
{
  char got[512];
  bool ok = parse_captured(text, strlen(text), got, sizeof got);
  char want[512];
  snprintf(want, sizeof want, "%s\n", message);
  CHECK_THAT(c, !ok && strcmp(got, want) == 0, "for the scene text\n    %s  expected stderr"
             "  %s  got stderr       %s", text, want, got);
}

Test(disc, statement_errors)
{
  Check c = CHECK("parser_load_string", "docs/scene-format.md, \"Errors\"");
  expect_error(&c, "material m\ndisc center 0 0 0 normal 0 0 0 radius 1 material m\n",
               "t.scene:2:26: expected a non-zero normal, found '0 0 0'");
  expect_error(&c, "material m\ndisc center 0 0 0 normal 0 1 0 radius 0 material m\n",
               "t.scene:2:39: expected a radius > 0, found '0'");
  expect_error(&c, "material m\ndisc center 0 0 0 normal 0 1 0 material m\n",
               "t.scene:2:42: expected 'radius' in this disc statement, found end of line");
  CHECK_DONE(&c);
}

/* scenes/disc.scene: the camera looks down at a disc of radius 2 below it;
 * the ray through the picture's centre meets it at the eye's height above
 * it, a ray past its rim misses it. */
Test(disc, the_scene_file_shows_a_disc)
{
  Scene s;
  scene_init(&s);
  cr_assert(parser_load_file("scenes/disc.scene", &s), "scenes/disc.scene did not parse "
            "(its message is above)");
  cr_assert(scene_prepare(&s, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
  Check c = CHECK("disc_hit_t", DOC);
  int disc = -1;
  for (int k = 0; k < s.n_instances && disc < 0; k++)
    if (s.instances[k].shape == SHAPE_DISC)
      disc = k;
  CHECK_REQUIRE(&c, disc >= 0, "scenes/disc.scene: expected a disc instance, found none");
  const Disc *d = &s.instances[disc].disc;
  Ray down = {.o = vec_make(d->center.x, d->center.y + 3.0f, d->center.z),
              .d = vec_make(0, -1, 0)};
  Hit h;
  CHECK_THAT(&c, scene_intersect(&s, down, INFINITY, &h) && h.inst == &s.instances[disc],
             "a ray straight down onto the centre of scenes/disc.scene's disc: expected to "
             "hit the disc (instance %d)", disc);
  CHECK_NEAR(&c, 3.0, h.t, 0.0, "that ray, from 3 above the centre: t");
  Ray past = {.o = vec_make(d->center.x + d->radius * 1.01f, d->center.y + 3.0f, d->center.z),
              .d = vec_make(0, -1, 0)};
  CHECK_NEAR(&c, INFINITY, disc_hit_t(d, past, INFINITY), 0.0,
             "a ray straight down 1.01 radii from the centre: a miss");
  CHECK_DONE(&c);
  scene_free(&s);
}
