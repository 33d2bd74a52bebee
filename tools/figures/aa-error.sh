#!/usr/bin/env bash
# Error of step 07's antialiasing against a converged render (the table of
# docs/07-antialiasing.md): RMSE over all channels of the .pfm films, linear
# floats not clamped, per sampler and camera sample count (--adaptive 0), and
# for adaptive sampling per sample count and threshold, with the rays traced
# (camera and shadow) and the render time. The reference is a 64 x 64
# jittered render with another seed, so no test render shares its samples.
# Usage: tools/figures/aa-error.sh [OUT_DIR]   (needs python3; make build first)
set -euo pipefail
bin=build/bin/07-antialiasing
out=${1:-build/aa-error}
mkdir -p "$out"
common=(--width 320 --height 240 --threads 2)
ref=$out/ref.pfm
[ -f "$ref" ] || $bin "${common[@]}" --quiet --sampler jitter --samples 4096 --adaptive 0 \
  --seed 4242 -o "$ref"
rmse() {
  python3 - "$1" "$2" <<'PY'
import array, math, sys
def load(p):
    f = open(p, 'rb'); f.readline(); f.readline()
    little = float(f.readline()) < 0
    a = array.array('f'); a.frombytes(f.read())
    if not little: a.byteswap()
    return a
a, b = load(sys.argv[1]), load(sys.argv[2])
print('%.3e' % math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)))
PY
}
printf '| sampler | samples | adaptive | RMSE | Mrays (camera + shadow) | time (s) |\n'
printf '|---|---|---|---|---|---|\n'
# row SAMPLER N ADAPTIVE: one line of the table.
row() {
  local f=$out/$1-$2-$3.pfm line rays
  line=$($bin "${common[@]}" --sampler "$1" --samples "$2" --adaptive "$3" -o "$f" 2>/dev/null)
  rays=$(sed -E 's/.* ([0-9.]+) Mrays in ([0-9.]+) s.*/\1 | \2/' <<<"$line")
  printf '| %s | %d | %s | %s | %s |\n' "$([ "$3" = 0 ] && echo "$1" || echo -)" "$2" \
    "$([ "$3" = 0 ] && echo off || echo "$3")" "$(rmse "$f" "$ref")" "$rays"
}
for s in center grid random jitter sobol; do
  for n in ${COUNTS:-1 4 16 64 256}; do
    [ $s = center ] && [ "$n" -gt 1 ] && continue
    row $s "$n" 0
  done
done
for n in ${COUNTS_ADAPTIVE:-16 64 256 1024}; do
  for a in 0.1 0.05 0.02; do
    row sobol "$n" "$a"
  done
done
