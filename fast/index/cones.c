/* The cones and discs of a small scene's spheres, seen from the eye and from
 * the lights (docs/performance.md, "Cones from the eye and the lights").
 *
 * Seen from a point P (the eye, a point light), a ball of centre c and
 * radius R fills the cone of directions w with w . a >= 0 and
 * (w . a)^2 >= (1 - s^2) |w|^2, where a is the unit vector toward c and
 * s = R / |c - P| the sine of the cone's half-angle.
 * - A ray leaving P in direction d can meet the ball only when d lies in
 *   that cone (its points are P + t d).
 * - A shadow ray from o whose end o + tmax d lies within rho of P can meet it
 *   only when o - P lies in the cone of the ball grown by rho: every point of
 *   the ray lies within rho of the segment from o to P, and every point of
 *   that segment lies along o - P seen from P.
 * Across a directional light, a ray along d can meet the ball only when its
 * origin, projected on the plane across d, lies within R of the centre's
 * projection.
 *
 * R is the radius padded by twice sphere_pad (cones.h, the hierarchy's margin),
 * so a grazing ray that sphere_hit_t accepts is never left out; s is widened
 * by 2^-9 and the discs by 2^-18 of the scene's size, far above the rounding
 * of the float comparisons (about 2^-20). A ball holding P (or nearly) is a
 * candidate for every ray. The comparisons run on all spheres at once (the
 * lanes of a GCC vector); they only choose which spheres are tested. */
#include "index/cones.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Lanes per comparison: 8 (256-bit vectors) where the build targets AVX,
 * else 4 (128 bits, which every x86-64 has: wider vectors passed without
 * AVX change the calling convention). */
#ifdef __AVX__
enum { LANES = 8 };
#else
enum { LANES = 4 };
#endif

enum {
  BLOCKS = CONES_MAX / LANES,
  MAX_LIGHTS = 8 /* cones for the first 8 point and 8 directional lights */
};

typedef float VF __attribute__((vector_size(LANES * sizeof(float))));
typedef int VI __attribute__((vector_size(LANES * sizeof(int))));

/* The cones seen from a point: unit axes a, squared cosines c2 of the
 * widened half-angles (2 in the lanes past the spheres: never met), and the
 * balls that hold the point. */
typedef struct PointCones {
  VF ax[BLOCKS], ay[BLOCKS], az[BLOCKS], c2[BLOCKS];
  vec3s p;
  float rho; /* shadow rays ending within rho of p are known */
  uint32_t always;
} PointCones;

/* The discs across a directional light. */
typedef struct Discs {
  vec3s d;              /* the rays' direction, bit for bit */
  vec3s e1, e2;         /* across d */
  float o_max;          /* origins farther out (max norm) are not looked up */
  VF u[BLOCKS], v[BLOCKS], r2[BLOCKS];
} Discs;

/* The lanes past the spheres never match: their c2 is 2 (usable directions
 * have |w| > 0) and their r2 is -1. */
struct Cones {
  int blocks;
  int ids[CONES_MAX];
  int n_points, n_discs;
  PointCones eye;
  PointCones points[MAX_LIGHTS];
  Discs discs[MAX_LIGHTS];
};

/* ---------------------------------------------------------------- queries */

/* |v|_inf by plain compares, per ray here. Unlike vec_max_abs (common/vec.h)
 * it promises nothing for a NaN component; the callers' tests are written
 * !(x <= limit), so that a NaN they see refuses the cone. */
static float max_abs(vec3s v)
{
  float x = fabsf(v.x), y = fabsf(v.y), z = fabsf(v.z);
  float m = x > y ? x : y;
  return m > z ? m : z;
}

/* Bit k set when lane k of `in` is true (all ones). */
static inline uint32_t lanes_mask(VI in)
{
#if defined __AVX__
  return (uint32_t)__builtin_ia32_movmskps256((VF)in);
#elif defined __SSE__
  return (uint32_t)__builtin_ia32_movmskps((VF)in);
#else
  uint32_t mask = 0;
  for (int k = 0; k < LANES; k++)
    mask |= (uint32_t)(in[k] & 1) << k;
  return mask;
#endif
}

/* A direction the comparisons below take in float without overflow,
 * underflow or NaN. */
static bool usable(vec3s w)
{
  float m = max_abs(w);
  return m >= 0x1p-60f && m <= 0x1p60f;
}

/* The spheres whose cone holds direction w (usable): w . a >= 0 and
 * (w . a)^2 >= c2 |w|^2. */
static inline uint32_t in_cones(const PointCones *pc, int blocks, vec3s w)
{
  float ww = w.x * w.x + w.y * w.y + w.z * w.z;
  uint32_t mask = pc->always;
  for (int b = 0; b < blocks; b++) {
    VF dot = w.x * pc->ax[b] + w.y * pc->ay[b] + w.z * pc->az[b];
    mask |= lanes_mask((dot >= 0.0f) & (dot * dot >= pc->c2[b] * ww)) << (LANES * b);
  }
  return mask;
}

const int *cones_spheres(const Cones *c)
{
  return c->ids;
}

bool cones_from_eye(const Cones *c, const Ray *r, uint32_t *mask)
{
  if (r->o.x != c->eye.p.x || r->o.y != c->eye.p.y || r->o.z != c->eye.p.z ||
      !usable(r->d))
    return false;
  *mask = in_cones(&c->eye, c->blocks, r->d);
  return true;
}

/* A ray along disc set ds: the discs holding its origin's projection. False
 * when the origin is too far out for the projection's rounding to stay
 * within the discs' widening (or not finite). */
static bool in_discs(const Discs *ds, int blocks, vec3s o, uint32_t *mask)
{
  if (!(max_abs(o) <= ds->o_max))
    return false;
  float u = o.x * ds->e1.x + o.y * ds->e1.y + o.z * ds->e1.z;
  float v = o.x * ds->e2.x + o.y * ds->e2.y + o.z * ds->e2.z;
  *mask = 0;
  for (int b = 0; b < blocks; b++) {
    VF du = u - ds->u[b], dv = v - ds->v[b];
    *mask |= lanes_mask(du * du + dv * dv <= ds->r2[b]) << (LANES * b);
  }
  return true;
}

bool cones_toward_light(const Cones *c, const Ray *r, float tmax, uint32_t *mask)
{
  for (int k = 0; k < c->n_discs; k++) {
    const Discs *ds = &c->discs[k];
    if (r->d.x == ds->d.x && r->d.y == ds->d.y && r->d.z == ds->d.z)
      return in_discs(ds, c->blocks, r->o, mask);
  }
  if (!(tmax < INFINITY) || c->n_points == 0)
    return false;
  /* The ray's end, and a bound on the exact end's distance to a light: the
   * distance found plus the rounding of o + tmax d and of e - p. */
  vec3s e = glms_vec3_add(r->o, glms_vec3_scale(r->d, tmax));
  float slack = 0x1p-21f * (max_abs(r->o) + tmax * max_abs(r->d));
  for (int k = 0; k < c->n_points; k++) {
    const PointCones *pc = &c->points[k];
    float rho = 2.0f * (max_abs(glms_vec3_sub(e, pc->p)) * (1.0f + 0x1p-20f) + slack);
    if (rho <= pc->rho) {
      vec3s w = glms_vec3_sub(r->o, pc->p);
      if (!usable(w))
        return false;
      *mask = in_cones(pc, c->blocks, w);
      return true;
    }
  }
  return false;
}

/* ---------------------------------------------------------------- building */

typedef struct Ball {
  double c[3], r; /* centre, radius padded as for the hierarchy's boxes */
} Ball;

static void point_cones(PointCones *pc, vec3s p, double rho, const Ball *b, int n)
{
  pc->p = p;
  pc->rho = (float)rho;
  pc->always = 0;
  for (int k = 0; k < BLOCKS * LANES; k++) {
    int blk = k / LANES, lane = k % LANES;
    pc->ax[blk][lane] = pc->ay[blk][lane] = pc->az[blk][lane] = 0.0f;
    pc->c2[blk][lane] = 2.0f;
    if (k >= n)
      continue;
    double a[3], dist2 = 0.0;
    for (int i = 0; i < 3; i++) {
      a[i] = b[k].c[i] - p.raw[i];
      dist2 += a[i] * a[i];
    }
    double dist = sqrt(dist2), reach = b[k].r + rho;
    double s = dist > reach ? reach / dist + 0x1p-9 : 1.0;
    if (!(s < 1.0)) { /* the ball holds p, or nearly: every direction */
      pc->always |= 1u << k;
      continue;
    }
    pc->ax[blk][lane] = (float)(a[0] / dist);
    pc->ay[blk][lane] = (float)(a[1] / dist);
    pc->az[blk][lane] = (float)(a[2] / dist);
    pc->c2[blk][lane] = (float)(1.0 - s * s);
  }
}

/* The discs across direction d; false when d is not a usable direction. */
static bool discs(Discs *ds, vec3s d, const Ball *b, int n)
{
  double w[3] = {d.x, d.y, d.z}, len = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (!(len > 0.0 && len < INFINITY))
    return false;
  for (int i = 0; i < 3; i++)
    w[i] /= len;
  /* e1: across w, from the axis w leans on least; e2 = w x e1. */
  int least = fabs(w[0]) <= fabs(w[1]) ? (fabs(w[0]) <= fabs(w[2]) ? 0 : 2)
                                       : (fabs(w[1]) <= fabs(w[2]) ? 1 : 2);
  double e1[3] = {-w[least] * w[0], -w[least] * w[1], -w[least] * w[2]};
  e1[least] += 1.0;
  double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (int i = 0; i < 3; i++)
    e1[i] /= l1;
  double e2[3] = {w[1] * e1[2] - w[2] * e1[1], w[2] * e1[0] - w[0] * e1[2],
                  w[0] * e1[1] - w[1] * e1[0]};
  ds->d = d;
  ds->e1 = vec_make((float)e1[0], (float)e1[1], (float)e1[2]);
  ds->e2 = vec_make((float)e2[0], (float)e2[1], (float)e2[2]);
  double extent = 0.0;
  for (int k = 0; k < n; k++)
    for (int i = 0; i < 3; i++)
      extent = fmax(extent, fabs(b[k].c[i]) + b[k].r);
  if (!(16.0 * extent <= 0x1p60))
    return false; /* the projections could overflow */
  ds->o_max = (float)(16.0 * extent);
  double pad = 0x1p-18 * 17.0 * extent;
  for (int k = 0; k < BLOCKS * LANES; k++) {
    int blk = k / LANES, lane = k % LANES;
    ds->u[blk][lane] = ds->v[blk][lane] = 0.0f;
    ds->r2[blk][lane] = -1.0f;
    if (k >= n)
      continue;
    /* The centre projected with the float axes the queries use. */
    const float *f1 = ds->e1.raw, *f2 = ds->e2.raw;
    ds->u[blk][lane] = (float)(b[k].c[0] * f1[0] + b[k].c[1] * f1[1] + b[k].c[2] * f1[2]);
    ds->v[blk][lane] = (float)(b[k].c[0] * f2[0] + b[k].c[1] * f2[1] + b[k].c[2] * f2[2]);
    double rad = b[k].r + pad;
    ds->r2[blk][lane] = (float)(rad * rad);
  }
  return true;
}

void cones_free(Cones *c)
{
  free(c);
}

Cones *cones_build(const Scene *scene, const int *ids, const Sphere *bounds, int n)
{
  if (n < 1 || n > CONES_MAX)
    return NULL;
  /* Aligned for the vectors' loads (calloc's 16 bytes are not enough). */
  size_t size = (sizeof(Cones) + 63) / 64 * 64;
  Cones *c = aligned_alloc(64, size);
  if (!c)
    return NULL;
  memset(c, 0, size);
  Ball b[CONES_MAX];
  for (int k = 0; k < n; k++) {
    const Sphere *s = &bounds[k];
    for (int i = 0; i < 3; i++)
      b[k].c[i] = s->center.raw[i];
    b[k].r = (double)s->radius + 2.0 * sphere_pad(s);
    c->ids[k] = ids[k];
  }
  c->blocks = (n + LANES - 1) / LANES;
  point_cones(&c->eye, scene->camera.eye, 0.0, b, n);
  for (int k = 0; k < scene->n_lights; k++) {
    const Light *light = &scene->lights[k];
    if (light->type == LIGHT_POINT && c->n_points < MAX_LIGHTS) {
      /* How far a shadow ray's end may stray from the light: 2^-12 of the
       * spheres' reach from it, far above what rounding and the shortened
       * tmax leave (2^-20 of the distance, ray_shadow_tmax). */
      double reach = 0.0;
      for (int m = 0; m < n; m++) {
        double dist2 = 0.0;
        for (int i = 0; i < 3; i++)
          dist2 += (b[m].c[i] - light->position.raw[i]) * (b[m].c[i] - light->position.raw[i]);
        reach = fmax(reach, sqrt(dist2) + b[m].r);
      }
      point_cones(&c->points[c->n_points++], light->position, 0x1p-12 * reach, b, n);
    } else if (light->type == LIGHT_DIRECTIONAL && c->n_discs < MAX_LIGHTS) {
      c->n_discs += discs(&c->discs[c->n_discs], glms_vec3_negate(light->direction), b, n);
    }
  }
#ifdef __AVX__
  /* gcc 12 can return from here with the upper halves of the vector
   * registers still in use (the balls above are filled 256 bits at a time
   * and a path without lights ends with no vzeroupper): every legacy SSE
   * instruction after that waits on them, libm's fmaxf in step 02's pixel
   * among them, which slowed that step's frame by half. */
  __builtin_ia32_vzeroupper();
#endif
  return c;
}
