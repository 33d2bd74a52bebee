/* An output file written under a temporary name beside its final one and
 * renamed into place when complete: an existing file is replaced only by a
 * whole new one, and a failure, a SIGINT, SIGTERM, SIGHUP or SIGXFSZ leaves
 * no temporary file behind. Introduced in step 01 (image files);
 * docs/reliability.md, "Output files". */
#ifndef RT_OUTFILE_H
#define RT_OUTFILE_H

#include <stdbool.h>
#include <stdio.h>

typedef struct OutFile {
  FILE *f;          /* write the contents here */
  const char *path; /* the final name */
  bool failed;      /* a write failed (set by whoever writes) */
  int err;          /* errno of the first failure */
} OutFile;

/* Create the temporary file for `path` (mode: the replaced file's, or 0666
 * less the umask for a new one) and watch the signals above until
 * outfile_close. Prints `image: cannot write 'PATH': REASON` and returns
 * false on failure. One OutFile open at a time per process. */
bool outfile_open(OutFile *out, const char *path);

/* Finish: when `ok` and every write succeeded, flush, close and rename into
 * place; otherwise remove the temporary file. Prints the reason of a failure
 * (errno of the failing call, or `err`); returns true when `path` now holds
 * the new contents. */
bool outfile_close(OutFile *out, bool ok);

#endif
