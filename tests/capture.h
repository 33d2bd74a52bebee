/* stderr sent to a temporary file while a test runs the parser in process,
 * to compare its messages. A sanitizer's report (make sanitize) would go to
 * that file too and the test would end with its [FAIL] line alone, no word
 * of why: while stderr is captured, the sanitizers' death callback copies
 * the file to the real stderr first.
 * docs/reliability.md, "Sanitizers". */
#ifndef RT_CAPTURE_H
#define RT_CAPTURE_H

#include <stdio.h>
#include <unistd.h>

/* From the sanitizers' runtime when the test is built with one; NULL else. */
extern void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

static int capture_real_ = -1, capture_file_ = -1;

static void capture_replay_(void)
{
  char buf[4096];
  ssize_t n;
  if (capture_real_ < 0 || lseek(capture_file_, 0, SEEK_SET) != 0)
    return;
  while ((n = read(capture_file_, buf, sizeof buf)) > 0)
    if (write(capture_real_, buf, (size_t)n) != n)
      return;
}

/* Send stderr to `file` (a tmpfile()) until capture_end. */
static inline void capture_begin(FILE *file)
{
  fflush(stderr);
  capture_file_ = fileno(file);
  capture_real_ = dup(2);
  dup2(capture_file_, 2);
  if (__sanitizer_set_death_callback)
    __sanitizer_set_death_callback(capture_replay_);
}

static inline void capture_end(void)
{
  fflush(stderr);
  dup2(capture_real_, 2);
  close(capture_real_);
  capture_real_ = capture_file_ = -1;
}

#endif
