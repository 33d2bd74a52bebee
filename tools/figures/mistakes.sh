#!/usr/bin/env bash
# Render the pictures of docs/05-shadows.md and docs/06-ambient.md into
# docs/img/: typical shadow and ambient mistakes (tools/figures/mistakes.c) beside the
# steps' right answers. Usage: [OUT=DIR] tools/figures/mistakes.sh BINDIR (make regen
# runs it through tools/figures/docimg.sh, OUT a scratch folder; default docs/img).
set -euo pipefail
bin=$1
size=(--width 400 --height 300 --threads 2 --quiet)
out_dir=${OUT:-docs/img}
mkdir -p "$out_dir"
run() { # run OUTPUT PROGRAM ARGS...
  local out=$out_dir/$1; shift
  echo "$*" "${size[*]}" -o "$out"
  "$@" "${size[@]}" -o "$out"
}
run 05-right.png          "$bin/05-shadows"
run 05-no-offset.png      "$bin/mistakes" no-offset
run 05-epsilon-tiny.png   "$bin/mistakes" epsilon=1e-3 --scene scenes/spheres-tiny.scene
run 05-right-tiny.png     "$bin/05-shadows" --scene scenes/spheres-tiny.scene
run 05-epsilon-huge.png   "$bin/mistakes" epsilon=1e-3 --scene scenes/spheres-huge.scene
run 05-right-huge.png     "$bin/05-shadows" --scene scenes/spheres-huge.scene
run 05-no-tmax.png        "$bin/mistakes" no-tmax --scene scenes/light-under-sphere.scene
run 05-right-tmax.png     "$bin/05-shadows" --scene scenes/light-under-sphere.scene
run 06-right.png          "$bin/06-ambient"
run 06-ambient-strong.png "$bin/06-ambient" --scene scenes/ambient-strong.scene
run 06-light-shadows.png  "$bin/mistakes" light-shadows --scene scenes/ambient.scene
