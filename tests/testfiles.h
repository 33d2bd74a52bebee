/* Files in tests: a whole file read, files counted by name. Shared by the
 * reliability tests and test_cli.c. */
#ifndef RT_TESTFILES_H
#define RT_TESTFILES_H

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The whole file, NUL-terminated, in a new buffer (the caller frees it); its
 * length in *n. NULL when unreadable. */
static inline char *testfiles_slurp(const char *path, long *n)
{
  FILE *f = fopen(path, "rb");
  if (!f)
    return NULL;
  fseek(f, 0, SEEK_END);
  long size = ftell(f);
  rewind(f);
  char *buf = size >= 0 ? malloc((size_t)size + 1) : NULL;
  *n = buf ? (long)fread(buf, 1, (size_t)size, f) : 0;
  if (buf)
    buf[*n] = '\0';
  fclose(f);
  return buf;
}

/* The files of folder `dir` whose name starts with `prefix`. */
static inline int testfiles_count(const char *dir, const char *prefix)
{
  DIR *d = opendir(dir);
  int n = 0;
  for (struct dirent *e; d && (e = readdir(d));)
    n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
  if (d)
    closedir(d);
  return n;
}

#endif
