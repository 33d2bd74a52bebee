#!/usr/bin/env bash
# Error of step 08's light sampling against a converged render (the table of
# docs/08-area-lights.md): RMSE over all channels of .pfm films clamped to
# [0, 1] (what a display shows), per light-sample count and pattern. One
# camera sample per pixel, so only the light's sampling differs from the
# reference (the same command with 4096 light samples): the camera's sample
# positions depend on seed and pixel, not on the light samples.
# Usage: tools/figures/area-light-error.sh [OUT_DIR]   (needs python3; make build first)
set -euo pipefail
bin=build/bin/08-area-lights
out=${1:-build/area-light-error}
ref_n=4096
mkdir -p "$out"
common=(--width 320 --height 240 --samples 1 --threads 2)
rmse() {
  python3 - "$1" "$2" <<'PY'
import array, math, sys
def load(p):
    f = open(p, 'rb'); f.readline(); w, h = map(int, f.readline().split())
    little = float(f.readline()) < 0
    a = array.array('f'); a.frombytes(f.read())
    if not little: a.byteswap()
    return a
a, b = load(sys.argv[1]), load(sys.argv[2])
c = lambda x: min(max(x, 0.0), 1.0)
print('%.3e' % math.sqrt(sum((c(x) - c(y)) ** 2 for x, y in zip(a, b)) / len(a)))
PY
}
printf '| pattern | light samples | RMSE | shadow+camera rays | time (s) |\n'
printf '|---|---|---|---|---|\n'
for s in random jitter sobol grid; do
  ref=$out/ref-$s.pfm
  [ -f "$ref" ] || $bin "${common[@]}" --adaptive 0 --quiet --sampler $s --light-samples $ref_n \
    -o "$ref"
  for n in 4 16 64 256; do
    f=$out/$s-$n.pfm
    line=$($bin "${common[@]}" --adaptive 0 --sampler $s --light-samples $n -o "$f" 2>/dev/null)
    rays=$(sed -E 's/.* ([0-9.]+) Mrays in ([0-9.]+) s.*/\1 M | \2/' <<<"$line")
    printf '| %s | %d | %s | %s |\n' $s $n "$(rmse "$f" "$ref")" "$rays"
  done
done
