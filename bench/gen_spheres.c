/* Scaling scenes for the benchmark (docs/benchmarks.md): N spheres resting on
 * the canonical scene's plane, on a jittered grid over a fixed patch, radius
 * shrinking as 1/sqrt(N) so every N covers about the same share of the
 * picture. Same camera and lights as scenes/spheres.scene.
 * Usage: gen_spheres N > FILE */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* A hash of (k, salt) to [0, 1): deterministic jitter, no library RNG. */
static double hash01(uint64_t k, uint64_t salt)
{
  uint64_t x = k * 0x9E3779B97F4A7C15ull + salt * 0xBF58476D1CE4E5B9ull;
  x ^= x >> 31;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 29;
  return (double)(x >> 11) * 0x1p-53;
}

int main(int argc, char **argv)
{
  long n = argc == 2 ? strtol(argv[1], NULL, 10) : 0;
  if (n < 1 || n > 100000000) {
    fprintf(stderr, "usage: gen_spheres N   (1 <= N <= 1e8)\n");
    return 2;
  }
  static const char *mats[] = {"red", "green", "blue", "gold", "white"};
  printf("# %ld spheres on the plane: bench/gen_spheres %ld\n", n, n);
  printf("film 800 600\ncamera eye 0 2.2 9 center 0 0.8 0 up 0 1 0 fov 40\n"
         "background 0.1 0.15 0.3\n"
         "material floor diffuse 0.7 0.7 0.7\n"
         "material red   diffuse 0.8 0.15 0.1  specular 0.6 0.6 0.6 shininess 64\n"
         "material green diffuse 0.15 0.7 0.2  specular 0.4 0.4 0.4 shininess 32\n"
         "material blue  diffuse 0.1 0.25 0.8  specular 0.8 0.8 0.8 shininess 128\n"
         "material gold  diffuse 0.8 0.6 0.15  specular 0.9 0.8 0.5 shininess 256\n"
         "material white diffuse 0.85 0.85 0.85 specular 0.3 0.3 0.3 shininess 16\n"
         "plane point 0 0 0 normal 0 1 0 material floor\n"
         "light point position 4 6 4 power 40 40 40\n"
         "light directional direction -1 -2 -1 irradiance 0.3 0.3 0.3\n");
  /* Patch x in [-6, 6], z in [-8, 4]: what the camera sees of the floor. */
  long side = (long)ceil(sqrt((double)n));
  double cell = 12.0 / (double)side, radius = 0.35 * cell;
  for (long k = 0; k < n; k++) {
    double x = -6.0 + cell * ((double)(k % side) + 0.5 + 0.3 * (hash01((uint64_t)k, 1) - 0.5));
    double z = -8.0 + cell * ((double)(k / side) + 0.5 + 0.3 * (hash01((uint64_t)k, 2) - 0.5));
    double r = radius * (0.6 + 0.4 * hash01((uint64_t)k, 3));
    printf("sphere center %.6g %.6g %.6g radius %.6g material %s\n", x, r, z, r, mats[k % 5]);
  }
  return 0;
}
