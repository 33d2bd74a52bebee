#!/usr/bin/env bash
# Render the pictures of docs/accuracy.md, "Pictures: a fixed epsilon at two
# scales": step 05's scene scaled by 10^4 and by 10^-4, as stress test 4
# writes it (tests/stress_shadows.c, scaled_scene, into BUILD/stress), lit
# with the fixed offset 1e-4 (tools/figures/mistakes.c) and by step 05
# (ray_spawn). Usage: [OUT=DIR] tools/figures/accuracy.sh BUILD (make regen
# runs it through tools/figures/docimg.sh, OUT a scratch folder; default docs/img).
set -euo pipefail
build=$1
out_dir=${OUT:-docs/img}
mkdir -p "$out_dir"
# Stress test 4 writes its scaled scenes first; its verdict is make stress's.
mkdir -p "$build/stress"
"$build/tests/stress" --filter='stress/t4_no_acne_and_no_leak_at_any_scale' --jobs 1 >/dev/null 2>&1 || true
size=(--width 320 --height 240 --threads 2 --quiet)
for scale in large:+4 small:-4; do
  scene=$build/stress/t4_${scale#*:}_0_0.scene
  [ -f "$scene" ] || { echo "accuracy: stress test 4 wrote no $scene" >&2; exit 1; }
  for pic in "epsilon:$build/bin/mistakes epsilon=1e-4" "robust:$build/bin/05-shadows"; do
    out=$out_dir/accuracy-${pic%%:*}-${scale%%:*}.png
    # shellcheck disable=SC2086 # the program and its variant
    echo ${pic#*:} --scene "$scene" "${size[*]}" -o "$out"
    # shellcheck disable=SC2086
    ${pic#*:} --scene "$scene" "${size[@]}" -o "$out"
  done
done
