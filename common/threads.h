/* The OpenMP runtime calls the renderer makes. A build without OpenMP (a
 * compiler without it, such as Apple's clang without libomp, or make
 * OPENMP=0) gets one thread's answers instead and ignores the pragmas: the
 * same pictures, on one thread (docs/performance.md, "Build flags"). */
#ifndef THREADS_H
#define THREADS_H

#ifdef _OPENMP
#include <omp.h>
/* The summary line's note after its thread count; --help's default. */
#define THREADS_BUILD_NOTE ""
#define THREADS_DEFAULT "all cores"
#else
#include <time.h>
#define THREADS_BUILD_NOTE ", built without OpenMP"
#define THREADS_DEFAULT "one, built without OpenMP"
static inline int omp_get_max_threads(void) { return 1; }
static inline int omp_get_num_threads(void) { return 1; }
static inline int omp_get_thread_num(void) { return 0; }
static inline void omp_set_num_threads(int threads) { (void)threads; }
static inline double omp_get_wtime(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
#endif

#endif
