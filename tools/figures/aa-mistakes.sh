#!/usr/bin/env bash
# Render the pictures of docs/07-antialiasing.md into docs/img/ (or OUT): sample
# patterns of one pixel and the typical antialiasing mistakes beside step
# 07's answers. Builds tools/figures/aa-mistakes.c itself. Usage: [OUT=DIR]
# tools/figures/aa-mistakes.sh (after make build; make regen runs it through
# tools/figures/docimg.sh, OUT a scratch folder; default docs/img).
set -euo pipefail
bin=build/bin
make --no-print-directory build/bin/07-antialiasing >/dev/null
# The Makefile's flags (make print-flags): cglm aligns its matrices by
# instruction set, so Scene's layout must match libcommon's.
eval "$(make --no-print-directory -s print-flags)"
# shellcheck disable=SC2086
$CC $CFLAGS $LDFLAGS -Isteps/07-antialiasing \
  tools/figures/aa-mistakes.c build/obj/gen/07-antialiasing-scene.o \
  build/libcommon.a $LDLIBS -o $bin/aa-mistakes
# shellcheck disable=SC2086
$CC $CFLAGS -Wno-missing-prototypes $LDFLAGS -Isteps/07-antialiasing \
  -Ibuild/gen/07-antialiasing -include step_manifest.h tools/figures/aa-samples.c build/obj/gen/07-antialiasing-scene.o \
  build/libcommon.a $LDLIBS -o $bin/aa-samples
img=${OUT:-docs/img}
mkdir -p "$img"
for s in grid random jitter sobol; do
  $bin/aa-mistakes points $s 16 $img/07-points-$s.png
done
size=(--width 400 --height 300 --threads 2 --quiet)
tmp=build/aa-mistakes
mkdir -p $tmp
# run NAME PROGRAM ARGS...: render NAME, then the zoomed box of the pearl rows.
run() {
  local name=$1; shift
  echo "$*" "${size[*]}" -o $img/$name.png
  "$@" "${size[@]}" -o $img/$name.png
  "$@" "${size[@]}" -o $tmp/$name.pfm
  $bin/aa-mistakes zoom $tmp/$name.pfm 96 95 100 50 $img/$name-zoom.png
}
s07=$bin/07-antialiasing
run 07-center-1     $s07 --sampler center --samples 1 --adaptive 0
run 07-grid-4       $s07 --sampler grid --samples 4 --adaptive 0
run 07-random-4     $s07 --sampler random --samples 4 --adaptive 0
run 07-jitter-4     $s07 --sampler jitter --samples 4 --adaptive 0
run 07-sobol-4      $s07 --sampler sobol --samples 4 --adaptive 0
run 07-same-numbers $bin/aa-mistakes same-numbers --sampler jitter --samples 4
run 07-default      $s07
run 07-converged    $s07 --sampler jitter --samples 1024 --adaptive 0
# Where the default's adaptive sampling put its samples, and the same zoom.
$bin/aa-samples 400 300 64 0.05 $img/07-samples.png
$bin/aa-samples 400 300 64 0.05 $tmp/07-samples.pfm
$bin/aa-mistakes zoom $tmp/07-samples.pfm 96 95 100 50 $img/07-samples-zoom.png
