/* Stress test 4 of docs/accuracy.md: step 05's render of its own scene,
 * scaled and translated, against a long-double reference renderer written
 * here (exact shadow rays that skip the convex shape they leave). Before it
 * counts acne, it checks that step 04's render of the unscaled scene (no
 * shadows) matches the reference without shadows: otherwise the camera, the
 * intersections or Phong are wrong, and it says so. */
#include <stdlib.h>

#include "check.h"

#include "app/image.h"
#include "app/parser.h"
#include "shapes.h"
#include "stress.h"

#define W 160
#define H 120
#define STEP04 BUILD_DIR "/bin/04-phong"
#define STEP05 BUILD_DIR "/bin/05-shadows"
#define MISTAKES BUILD_DIR "/bin/mistakes"

typedef long double LD;
typedef struct L3 {
  LD x, y, z;
} L3;

static L3 l3(vec3s v) { return (L3){v.x, v.y, v.z}; }
static L3 add(L3 a, L3 b) { return (L3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static L3 sub(L3 a, L3 b) { return (L3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static L3 mul(L3 a, LD s) { return (L3){a.x * s, a.y * s, a.z * s}; }
static LD dot(L3 a, L3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static L3 unit(L3 a) { return mul(a, 1.0L / sqrtl(dot(a, a))); }
static L3 cross(L3 a, L3 b)
{
  return (L3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/* Exact (long double) nearest root in (0, tmax) of the unit ray (o, d) with
 * sphere k, and the ray line's clearance from its silhouette |h - r|. */
static LD ref_sphere(const Sphere *s, L3 o, L3 d, LD tmax, LD *clear)
{
  L3 f = sub(o, l3(s->center));
  LD b = dot(f, d), r = s->radius, h2 = dot(f, f) - b * b;
  *clear = -b > 0.0L ? fabsl(sqrtl(h2 > 0.0L ? h2 : 0.0L) - r) : INFINITY;
  LD disc = r * r - h2;
  if (disc < 0.0L)
    return INFINITY;
  LD t0 = -b - sqrtl(disc), t1 = -b + sqrtl(disc);
  if (t0 > 0.0L && t0 < tmax)
    return t0;
  return (t1 > 0.0L && t1 < tmax) ? t1 : INFINITY;
}

static LD ref_plane(const Plane *pl, L3 o, L3 d, LD tmax)
{
  LD t = dot(sub(l3(pl->point), o), l3(pl->normal)) / dot(d, l3(pl->normal));
  return (t > 0.0L && t < tmax) ? t : INFINITY;
}

/* What a float render cannot decide (docs/accuracy.md, test 4). The
 * reference starts from step 05's float eye. A float camera ray's direction
 * is within CAM_ANGLE of the exact one: each component within 3 x 2^-24
 * (camera.c rounds a double basis once, then 2 float roundings for the film
 * point, 5 for the matrix product, 2 for the normalization; the worst of the
 * 40 cameras measures 2.64). A float ray misjudges hit or miss only when the
 * line passes within DECIDE x distance of the silhouette (test 2). */
#define CAM_ANGLE (3.0L * 1.7320508075688772935L * 0x1p-24L)
#define DECIDE (2.0L * 0x1p-24L)

/* Any shape but `skip` on the segment (o, o + tmax d)? `amb` is set when a
 * sphere's silhouette passes within `shift` + DECIDE x distance of the
 * segment's line (the float ray's origin may be `shift` off). */
static bool ref_occluded(const Scene *sc, int skip, L3 o, L3 d, LD tmax, LD shift, bool *amb)
{
  bool hit = false;
  for (int k = 0; k < sc->n_shapes; k++) {
    const Instance *in = &sc->instances[k];
    if (k == skip) /* convex shapes: a ray leaving one never meets it again */
      continue;
    LD clear = INFINITY;
    LD t = in->shape == SHAPE_SPHERE ? ref_sphere(&in->sphere, o, d, tmax, &clear)
                                     : ref_plane(&in->plane, o, d, tmax);
    hit |= t < tmax;
    if (in->shape == SHAPE_SPHERE) {
      L3 f = sub(o, l3(in->sphere.center));
      *amb |= clear < shift + DECIDE * sqrtl(dot(f, f));
    }
  }
  return hit;
}

/* The reference with shadows (step 05's model) or without (step 04's). */
static bool ref_shadows = true;

/* Phong at the exact hit (p, n) of shape k seen from eye (step 05's model). */
static L3 ref_shade(const Scene *sc, int k, L3 p, L3 n, L3 eye, LD shift, bool *amb)
{
  const Material *m = &sc->materials[sc->instances[k].material];
  L3 c = {0, 0, 0}, v = unit(sub(eye, p));
  for (int q = 0; q < sc->n_lights; q++) {
    const Light *lt = &sc->lights[q];
    L3 l, li;
    LD dist;
    if (lt->type == LIGHT_POINT) {
      L3 to = sub(l3(lt->position), p);
      dist = sqrtl(dot(to, to));
      l = mul(to, 1.0L / dist);
      li = mul(l3(lt->power), 1.0L / (dist * dist));
    } else {
      l = mul(l3(lt->direction), -1.0L);
      dist = INFINITY;
      li = l3(lt->irradiance);
    }
    LD nl = dot(n, l);
    if (!(nl > 0.0L) || (ref_shadows && ref_occluded(sc, k, p, l, dist, shift, amb)))
      continue;
    L3 r = sub(mul(n, 2.0L * nl), l);
    LD rv = dot(r, v), lobe = powl(rv > 0.0L ? rv : 0.0L, m->shininess);
    c.x += li.x * (m->diffuse.x * nl + m->specular.x * lobe);
    c.y += li.y * (m->diffuse.y * nl + m->specular.y * lobe);
    c.z += li.z * (m->diffuse.z * nl + m->specular.z * lobe);
  }
  return c;
}

/* The reference colour along the exact camera ray through film point
 * (nx, ny); *amb is set when the float render cannot decide: a silhouette
 * passes within the float camera ray's error of the exact ray, or within the
 * float hit point's error of a shadow ray. `coord` bounds the coordinates of
 * the shapes and lights (not of the eye). */
/* The exact camera ray's direction through film point (nx, ny). */
static L3 ref_camera_dir(const Camera *cam, LD nx, LD ny)
{
  L3 w = unit(sub(l3(cam->eye), l3(cam->center)));
  L3 u = unit(cross(l3(cam->up), w)), v = cross(w, u);
  LD hh = tanl(0.5L * cam->fov_y_deg * 3.14159265358979323846264L / 180.0L), hw = hh * W / H;
  return unit(add(add(mul(u, -hw + 2.0L * hw * nx), mul(v, -hh + 2.0L * hh * ny)), mul(w, -1.0L)));
}

static L3 ref_pixel(const Scene *sc, LD nx, LD ny, LD coord, bool *amb)
{
  const Camera *cam = &sc->camera;
  L3 eye = l3(cam->eye), d = ref_camera_dir(cam, nx, ny);
  int best = -1;
  LD t = INFINITY;
  for (int k = 0; k < sc->n_shapes; k++) {
    const Instance *in = &sc->instances[k];
    LD clear = INFINITY;
    LD tk = in->shape == SHAPE_SPHERE ? ref_sphere(&in->sphere, eye, d, t, &clear)
                                      : ref_plane(&in->plane, eye, d, t);
    if (in->shape == SHAPE_SPHERE) {
      L3 f = sub(eye, l3(in->sphere.center));
      *amb |= clear < (CAM_ANGLE + DECIDE) * sqrtl(dot(f, f));
    }
    if (tk < t)
      t = tk, best = k;
  }
  if (best < 0)
    return l3(sc->background);
  const Instance *in = &sc->instances[best];
  L3 p = add(eye, mul(d, t));
  L3 n = in->shape == SHAPE_SPHERE ? mul(sub(p, l3(in->sphere.center)), 1.0L / in->sphere.radius)
                                   : l3(in->plane.normal);
  if (dot(n, d) > 0.0L)
    n = mul(n, -1.0L);
  /* The float hit point lies up to CAM_ANGLE t / cos(incidence) away along
   * the surface (the camera ray's error), plus 4 ulps of t (its distance),
   * plus the refined point's error and the spawn offset: sqrt(3) p_err +
   * 2 sqrt(3) p_err, p_err = 2^-22 (|c| + r) <= 4 2^-24 coord. */
  LD shift = CAM_ANGLE * t / fabsl(dot(n, d)) + 8.0L * 0x1p-24L * t + 21.0L * 0x1p-24L * coord;
  return ref_shade(sc, best, p, n, eye, shift, amb);
}

/* The reference picture as a band [lo, hi] per channel: the exact colour at
 * the pixel centre and at four points `jitter` away in film units, the
 * uncertainty of a float camera ray (a few ulps of its angle). amb[] marks
 * pixels where some silhouette is within the float error of a ray. */
static void ref_render(const Scene *sc, LD coord, LD jitter, float *lo, float *hi, bool *amb)
{
  static const int off[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  /* Rows in parallel: each pixel's band depends on the scene alone. */
#pragma omp parallel for schedule(dynamic, 4)
  for (int j = 0; j < H; j++) {
    for (int i = 0; i < W; i++) {
      size_t q = (size_t)j * W + i;
      bool aside = false; /* only the centre's rays are the float render's */
      amb[q] = false;
      for (int k = 0; k < 5; k++) {
        L3 c = ref_pixel(sc, (i + 0.5L) / W + off[k][0] * jitter,
                         (j + 0.5L) / H + off[k][1] * jitter, coord, k ? &aside : &amb[q]);
        float rgb[3] = {(float)c.x, (float)c.y, (float)c.z};
        for (int ch = 0; ch < 3; ch++) {
          lo[3 * q + ch] = k ? fminf(lo[3 * q + ch], rgb[ch]) : rgb[ch];
          hi[3 * q + ch] = k ? fmaxf(hi[3 * q + ch], rgb[ch]) : rgb[ch];
        }
      }
    }
  }
}

/* The scene file of `base` scaled by s and translated by T (1, 0.5, -0.75);
 * far: the eye 1000 times farther from the centre with a 1000 times
 * narrower field of view. Point lights' power scales by s^2 (same image). */
static void write_scene(const Scene *base, const char *path, double s, double T, bool far)
{
  FILE *f = fopen(path, "w");
  cr_assert(f, "cannot write %s", path);
#define TX(v, k) (s * (double)(v).raw[k] + T * (const double[]){1.0, 0.5, -0.75}[k])
#define PT(v) TX(v, 0), TX(v, 1), TX(v, 2)
  const Camera *c = &base->camera;
  double fov = c->fov_y_deg, m = far ? 1000.0 : 1.0;
  vec3s eye = glms_vec3_add(c->center, glms_vec3_scale(glms_vec3_sub(c->eye, c->center), (float)m));
  if (far)
    fov = 2.0 * atan(tan(0.5 * fov * GLM_PI / 180.0) / m) * 180.0 / GLM_PI;
  fprintf(f, "film %d %d\ncamera eye %.9g %.9g %.9g center %.9g %.9g %.9g up %.9g %.9g %.9g fov %.9g\n",
          W, H, PT(eye), PT(c->center), c->up.x, c->up.y, c->up.z, fov);
  fprintf(f, "background %.9g %.9g %.9g\n", base->background.x, base->background.y, base->background.z);
  for (int k = 0; k < base->n_materials; k++) {
    const Material *mt = &base->materials[k];
    fprintf(f, "material %s ambient %.9g %.9g %.9g diffuse %.9g %.9g %.9g specular %.9g %.9g %.9g "
            "shininess %.9g\n", mt->name, mt->ambient.x, mt->ambient.y, mt->ambient.z,
            mt->diffuse.x, mt->diffuse.y, mt->diffuse.z, mt->specular.x, mt->specular.y,
            mt->specular.z, mt->shininess);
  }
  for (int k = 0; k < base->n_shapes; k++) {
    const Instance *in = &base->instances[k];
    const char *mat = base->materials[in->material].name;
    if (in->shape == SHAPE_PLANE)
      fprintf(f, "plane point %.9g %.9g %.9g normal %.9g %.9g %.9g material %s\n",
              PT(in->plane.point), in->plane.normal.x, in->plane.normal.y, in->plane.normal.z, mat);
    else
      fprintf(f, "sphere center %.9g %.9g %.9g radius %.9g material %s\n", PT(in->sphere.center),
              s * in->sphere.radius, mat);
  }
  for (int k = 0; k < base->n_lights; k++) {
    const Light *lt = &base->lights[k];
    if (lt->type == LIGHT_POINT)
      fprintf(f, "light point position %.9g %.9g %.9g power %.9g %.9g %.9g\n", PT(lt->position),
              s * s * lt->power.x, s * s * lt->power.y, s * s * lt->power.z);
    else if (lt->type == LIGHT_DIRECTIONAL)
      fprintf(f, "light directional direction %.9g %.9g %.9g irradiance %.9g %.9g %.9g\n",
              lt->direction.x, lt->direction.y, lt->direction.z, lt->irradiance.x,
              lt->irradiance.y, lt->irradiance.z);
  }
#undef PT
#undef TX
  fclose(f);
}

/* Render `scene` with `cmd` (a binary and its variant) into a new buffer. */
static float *render_with(const char *cmd, const char *scene, const char *out)
{
  char line[1024];
  snprintf(line, sizeof line, "%s --scene %s -o %s --threads 2 --quiet", cmd, scene, out);
  cr_assert(system(line) == 0, "the step's program failed (a crash or an error in a step's "
            "function; run the command to see): %s", line);
  int w, h;
  float *rgb;
  cr_assert(image_load(out, &w, &h, &rgb) && w == W && h == H, "cannot read %s", out);
  return rgb;
}

typedef struct Count {
  long acne, leak;
  int first[8], n_first; /* the first pixels outside the band */
} Count;

/* Pixels outside the reference band by more than shading round-off (1e-3
 * relative), undecidable ones aside: darker = acne, brighter = leak. */
static Count compare(const float *img, const float *lo, const float *hi, const bool *amb)
{
  Count n = {0, 0, {0}, 0};
  for (int p = 0; p < W * H; p++) {
    if (amb[p])
      continue;
    bool dark = false, bright = !isfinite(img[3 * p]);
    for (int c = 0; c < 3; c++) {
      float x = img[3 * p + c];
      dark |= x < lo[3 * p + c] - 1e-3f * (1.0f + lo[3 * p + c]);
      bright |= x > hi[3 * p + c] + 1e-3f * (1.0f + hi[3 * p + c]);
    }
    n.acne += dark;
    n.leak += bright && !dark;
    if ((dark || bright) && n.n_first < 8)
      n.first[n.n_first++] = p;
  }
  return n;
}

/* Whose fault a pixel outside the band is: the hit that step 05 shades
 * there, checked against long double as steps 02's tests check it. The float
 * camera ray through the pixel centre (camera_ray is checked for each
 * scene) meets the scene; its t must be within 16 ulps of the exact root for
 * that ray, the normal within 16 x 2^-24 (1 + |o - c| / r) of the direction of
 * (o - c) + t d (test_sphere's bound), and p within 3 p_err and the
 * rounding of its own coordinates of the ray's point at t. When all hold, the hit is right and the shadow ray's start is to
 * blame. Returns the function at fault, "" for ray_spawn, shade_visible, and
 * in *why what was off. */
static const char *blame_pixel(Scene *sc, int q, char *why, size_t size)
{
  Ray r = camera_ray(&sc->camera, (q % W + 0.5f) / W, (q / W + 0.5f) / H);
  Hit h;
  if (!scene_intersect(sc, r, INFINITY, &h))
    return "";
  L3 o = l3(r.o), d = unit(l3(r.d));
  LD dlen = sqrtl(dot(l3(r.d), l3(r.d)));
  if (h.inst->shape == SHAPE_SPHERE) {
    const Sphere *s = &h.inst->sphere;
    LD clear, want = ref_sphere(s, o, d, INFINITY, &clear) / dlen;
    double ulps = fabs((double)(h.t - want)) / stress_ulp((double)want);
    if (!(ulps <= 16.0)) {
      snprintf(why, size, "its distance t = %.9g is %.3g ulps off the exact %.9Lg", h.t, ulps,
               want);
      return "sphere_hit_t";
    }
    L3 rel = add(sub(o, l3(s->center)), mul(l3(r.d), (LD)h.t)), n = unit(rel);
    if (dot(n, l3(r.d)) > 0.0L)
      n = mul(n, -1.0L);
    L3 dn = sub(l3(h.n), n), f = sub(o, l3(s->center));
    LD err = fmaxl(fabsl(dn.x), fmaxl(fabsl(dn.y), fabsl(dn.z))) / 0x1p-24L;
    LD bound = 16.0L * (1.0L + sqrtl(dot(f, f)) / s->radius);
    if (!(err <= bound)) {
      snprintf(why, size, "the normal is %.3Lg x 2^-24 off the direction of (o - c) + t d (at "
               "most %.3Lg): form it from (o - c) + t d, not from p - c", err, bound);
      return "sphere_hit_fill";
    }
  }
  L3 at = add(o, mul(l3(r.d), (LD)h.t)), off = sub(l3(h.p), at);
  /* p's coordinates are rounded to ulps of themselves (an axis plane's hit
   * has p_err = 0 and the plane's coordinate exactly, the others rounded). */
  LD gap = sqrtl(dot(off, off)),
     allowed = 3.0L * h.p_err + 8.0L * 0x1p-24L * (vec_max_abs(h.p) + h.t * dlen);
  if (!(gap <= allowed)) {
    snprintf(why, size, "p is %.3Lg from the ray's point at t, p_err %.3g", gap, h.p_err);
    return h.inst->shape == SHAPE_SPHERE ? "sphere_hit_fill" : "plane_hit_fill";
  }
  return "";
}

/* The scene of `base` at scale s, translation T, far camera or not, in
 * STRESS_DIR; its path in `scene`, loaded into sc. */
static void scaled_scene(const Scene *base, double s, double T, bool far, char *scene,
                         size_t size, Scene *sc)
{
  snprintf(scene, size, STRESS_DIR "/t4_%+d_%d_%d.scene", (int)lround(log10(s)), T > 0.0, far);
  write_scene(base, scene, s, T, far);
  scene_init(sc);
  cr_assert(parser_load_file(scene, sc), "cannot load the test's own scene %s", scene);
}

/* The first precondition of test 4: the scaled scenes are seen from up to
 * 10^4 radii (the far camera); their hit points come from sphere_hit_t, so
 * its distance must be right there before acne means anything. Central rays
 * at 1.1 .. 10^5 radii against the long-double root (16 ulps: test 1 asks 4). */
static void require_precise_sphere(void)
{
  Check c = CHECK("sphere_hit_t (step 02)", "docs/02-intersection.md, \"What you write\"");
  for (int k = 0; k < 400; k++) {
    Rng g = rng_make(40, 0, (uint32_t)k);
    double ratio = stress_log10u(&g, log10(1.1), 5.0);
    Sphere s = {.center = glms_vec3_scale(stress_unit(&g), (float)stress_log10u(&g, -2.0, 2.0)),
                .radius = (float)stress_log10u(&g, -2.0, 2.0)};
    vec3s u = stress_unit(&g);
    vec3s o = glms_vec3_add(s.center, glms_vec3_scale(u, (float)(ratio * s.radius)));
    L3 d = unit(sub(l3(s.center), l3(o)));
    Ray r = {.o = o, .d = stress_stored(vec_make((float)d.x, (float)d.y, (float)d.z))};
    LD clear, want = ref_sphere(&s, l3(r.o), unit(l3(r.d)), INFINITY, &clear);
    float t = sphere_hit_t(&s, r, INFINITY);
    double ulps = fabs((double)(t - want)) / stress_ulp((double)want);
    CHECK_REQUIRE(&c, ulps <= 16.0, "a central ray toward a sphere %.3g radii away is off by "
                  "%.3g ulps (t = %.9g, exact %.9Lg): the scaled scenes of this test are seen "
                  "from up to 10^4 radii, so it cannot tell acne from a wrong distance; "
                  "stress test 1 says which refinement is missing", ratio, ulps, t, want);
  }
}

/* The second precondition of test 4: step 04's render of the unscaled scene matches
 * the long-double reference without shadows. Acne is only acne when the
 * camera, the intersections and Phong are right. */
static void require_plain_render(const Scene *base, float *lo, float *hi, bool *amb)
{
  char scene[256];
  Scene sc;
  scaled_scene(base, 1.0, 0.0, false, scene, sizeof scene, &sc);
  ref_shadows = false;
  ref_render(&sc, 10.0L, 4.0L * 0x1p-24L, lo, hi, amb);
  ref_shadows = true;
  float *img = render_with(STEP04, scene, STRESS_DIR "/t4_plain_04.pfm");
  Count n = compare(img, lo, hi, amb);
  free(img);
  scene_free(&sc);
  Check c = CHECK("camera_ray, sphere_hit_t, plane_hit_t, shade_phong_light (steps 02 to 04)",
                  "docs/04-phong.md, \"What you write\"");
  CHECK_REQUIRE(&c, n.acne + n.leak == 0, "step 04's render of scenes/spheres.scene at 160x120 "
                "(no shadows) differs from the long-double reference without shadows in %ld "
                "of %d pixels (%ld darker, %ld brighter): the camera, an intersection or Phong "
                "is wrong, not the shadows; fix `make test-step 2`, `3` and `4` first (this "
                "test measures shadow acne and light leaks only)", n.acne + n.leak, W * H,
                n.acne, n.leak);
}

/* The largest angle between camera_ray's directions and the exact ones, over
 * a 5 x 5 grid of pixel centres. */
static double camera_error(const Scene *sc)
{
  LD worst = 0.0L;
  for (int j = 0; j < 5; j++)
    for (int i = 0; i < 5; i++) {
      LD nx = (32 * i + 16.5L) / W, ny = (24 * j + 12.5L) / H;
      Ray r = camera_ray(&sc->camera, (float)nx, (float)ny);
      L3 want = ref_camera_dir(&sc->camera, (float)nx, (float)ny), got = unit(l3(r.d));
      L3 x = cross(want, got);
      LD a = sqrtl(dot(x, x));
      worst = isnan(a) || a > worst ? a : worst;
    }
  return (double)worst;
}

Test(stress, t4_no_acne_and_no_leak_at_any_scale, .timeout = 600)
{
  stress_step(5);
  Scene base;
  scene_init(&base);
  cr_assert(parser_load_file("scenes/spheres.scene", &base), "cannot load the step-05 scene");
  float *lo = malloc(sizeof(float) * 3 * W * H), *hi = malloc(sizeof(float) * 3 * W * H);
  bool *amb = malloc(sizeof(bool) * W * H);
  cr_assert(lo && hi && amb, "out of memory");
  require_precise_sphere();
  require_plain_render(&base, lo, hi, amb);
  stress_table("t4_shadows", "Test 4: pixels with shadow acne (darker than the reference) / "
               "light leaks (brighter), step 05 against a long-double reference, 160x120; "
               "fixed epsilon = tools/figures/mistakes.c epsilon=1e-4",
               "| scale | translation | camera | undecidable | step 05 acne | step 05 leak | "
               "fixed-eps acne | fixed-eps leak |\n|---|---|---|---|---|---|---|---|");
  Check c = CHECK_RELYING("ray_spawn, shade_visible (step 05)",
                          "docs/05-shadows.md, \"Self-intersection: where the shadow ray starts\"",
                          "camera_ray (step 03, checked for each scene), sphere_hit_t "
                          "(step 02, checked at 1.1 .. 10^5 radii), light_incident, "
                          "shade_phong_light (step 04, checked at scale 1 without shadows)");
  Check cam = CHECK("camera_ray (step 03)", "docs/03-camera.md, \"What you write\"");
  double cam_worst = 0.0;
  long bad = 0, blamed = 0;
  for (int e = -4; e <= 5; e++) {
    for (int tr = 0; tr < 2; tr++) {
      for (int far = 0; far < 2; far++) {
        double s = pow(10.0, e), T = tr ? fmin(1e5, 1e3 * s) : 0.0;
        char scene[256], out[256], outeps[256];
        Scene sc;
        scaled_scene(&base, s, T, far, scene, sizeof scene, &sc);
        /* Acne is only acne when the camera rays are right (CAM_ANGLE). */
        double cam_err = camera_error(&sc);
        cam_worst = fmax(cam_worst, cam_err);
        CHECK_THAT(&cam, cam_err <= 2.0 * CAM_ANGLE, "step 05's scene scaled by %g, moved by "
                   "%g, %s camera (the eye %.3g from the origin): camera rays are off by "
                   "%.3g rad (at most %.3g asked): take the direction as V^-1 (p, 0), not "
                   "V^-1 (p, 1) - V^-1 (0, 0, 0, 1), whose eye coordinates round away the "
                   "direction's low bits far from the origin", s, T,
                   far ? "a far, narrow" : "the usual", glms_vec3_norm(sc.camera.eye), cam_err,
                   (double)(2.0L * CAM_ANGLE));
        if (!(cam_err <= 2.0 * CAM_ANGLE)) {
          scene_free(&sc);
          continue;
        }
        snprintf(out, sizeof out, STRESS_DIR "/t4_%+d_%d_%d.pfm", e, tr, far);
        snprintf(outeps, sizeof outeps, STRESS_DIR "/t4_%+d_%d_%d_eps.pfm", e, tr, far);
        /* Coordinates up to `coord` (eye included); a float camera ray's
         * angle is good to a few 2^-24, plus the rounding of its hit point
         * seen from the eye: the band's half-width. The shapes and lights
         * alone stay within T + 10 s. */
        double coord = fmax(T, 10.0 * s * (far ? 1000.0 : 1.0));
        double dist = 9.0 * s * (far ? 1000.0 : 1.0), half = tan(0.5 * sc.camera.fov_y_deg * GLM_PI / 180.0);
        double jitter = 4.0 * 0x1p-24 * (1.0 + coord / dist) / (2.0 * half);
        ref_render(&sc, T + 10.0 * s, jitter, lo, hi, amb);
        float *img = render_with(STEP05, scene, out);
        float *eps = render_with(MISTAKES " epsilon=1e-4", scene, outeps);
        long n_amb = 0;
        for (int p = 0; p < W * H; p++)
          n_amb += amb[p];
        Count rob = compare(img, lo, hi, amb), txt = compare(eps, lo, hi, amb);
        stress_row("t4_shadows", "| %g | %g | %s | %ld | %ld | %ld | %ld | %ld |", s, T,
                   far ? "1000x, narrow" : "usual", n_amb, rob.acne, rob.leak, txt.acne, txt.leak);
        /* A pixel whose hit is wrong is that function's fault, not the
         * shadow ray's: said once per scene, and the pixel not counted. */
        cr_assert(scene_prepare(&sc, SCENE_CAMERA | SCENE_LIGHTS), "out of memory");
        for (int k = 0; k < rob.n_first; k++) {
          char why[256];
          const char *fn = blame_pixel(&sc, rob.first[k], why, sizeof why);
          if (!*fn)
            continue;
          char name[64];
          snprintf(name, sizeof name, "%s (step 02)", fn);
          Check hc = CHECK(name, "docs/02-intersection.md, \"What you write\"");
          CHECK_THAT(&hc, false, "step 05's scene scaled by %g, moved by %g, %s camera: pixel "
                     "(%d, %d) (from the bottom) differs from the long-double reference, and "
                     "the hit step 05 shades there is wrong: %s", s, T,
                     far ? "a far, narrow" : "the usual", rob.first[k] % W, rob.first[k] / W, why);
          blamed++;
          rob.acne = rob.leak = 0; /* the shadow ray is not judged on a wrong hit */
          break;
        }
        CHECK_THAT(&c, rob.acne == 0 && rob.leak == 0,
                   "step 05's scene scaled by %g, moved by %g, %s camera: %ld pixels darker "
                   "than the reference (shadow acne: a surface shadows itself, so the shadow "
                   "ray starts too close, or inside, at this scale) and %ld brighter (light "
                   "leaks: it starts too far off, e.g. a fixed epsilon at a small scale, or "
                   "stops past the light); the offset must follow the hit's error bound, "
                   "push = 2 p_err |n|_1, at every scale", s, T, far ? "a far, narrow" : "the "
                   "usual", rob.acne, rob.leak);
        bad += rob.acne + rob.leak;
        free(img), free(eps);
        scene_free(&sc);
      }
    }
  }
  CHECK_DONE(&cam);
  CHECK_DONE(&c);
  free(lo), free(hi), free(amb);
  scene_free(&base);
  cr_log_info("test 4: %ld acne or leak pixels over all scales, %ld scenes with a wrong hit; "
              "camera rays within %.3g rad", bad, blamed, cam_worst);
}
