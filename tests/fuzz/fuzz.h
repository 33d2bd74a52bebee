/* Fuzzing entry points (docs/reliability.md, "Fuzzing"): each takes any
 * bytes, feeds them to the program's own functions and aborts only on a bug
 * (a sanitizer report, or an answer that contradicts another). libFuzzer
 * calls them (tests/fuzz/libfuzzer.c, make fuzz); tests/test_fuzz_corpus.c
 * replays the regression corpus through them in make test. */
#ifndef RT_FUZZ_H
#define RT_FUZZ_H

#include <stddef.h>
#include <stdint.h>

/* The scene reader, scene_prepare and accel_build; the index's closest hits
 * compared with the plain loop's for a few camera rays. */
void fuzz_scene(const uint8_t *data, size_t size);

/* The command line: the bytes split at NULs into argv for cli_parse. */
void fuzz_cli(const uint8_t *data, size_t size);

/* A tiny render (at most 12 x 9 pixels, 4 samples, 4 light samples, one
 * thread) of the parsed scene through step 08's pixel function; every pixel
 * must be a number (no NaN). */
void fuzz_render(const uint8_t *data, size_t size);

/* Step 08's main, renamed when built for fuzzing: app_run is then
 * fuzz_app_run, which keeps the step's description for fuzz_render. */
struct Step;
int fuzz_step08_main(int argc, char **argv);
int fuzz_app_run(int argc, char **argv, const struct Step *step);

#endif
