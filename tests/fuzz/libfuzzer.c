/* libFuzzer's entry, one binary per target: built with -DFUZZ_ENTRY=fuzz_scene
 * (or fuzz_cli, fuzz_render) by mk/fuzz.mk. docs/reliability.md, "Fuzzing". */
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  FUZZ_ENTRY(data, size);
  return 0;
}
