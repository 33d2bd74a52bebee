#!/usr/bin/env bash
# Error of step 07's antialiasing against a converged render (the table of
# docs/07-antialiasing.md): RMSE over all channels of the .pfm films, linear
# floats not clamped, per sampler, camera sample count and adaptive on/off,
# with the rays traced (camera and shadow) and the render time. The reference is a 64 x 64
# jittered render with another seed, so no test render shares its samples.
# Usage: tools/aa-error.sh [OUT_DIR [THRESHOLD]]   (needs python3; make build first)
set -euo pipefail
bin=build/bin/07-antialiasing
out=${1:-build/aa-error}
threshold=${2:-0.05}
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
for s in center grid random jitter sobol; do
  for n in ${COUNTS:-1 4 16 64 256}; do
    for a in 0 "$threshold"; do
      [ "$a" != 0 ] && [ "$n" -le 4 ] && continue
      [ $s = center ] && [ "$n" -gt 1 ] && continue
      f=$out/$s-$n-$a.pfm
      line=$($bin "${common[@]}" --sampler $s --samples "$n" --adaptive "$a" -o "$f" 2>/dev/null)
      rays=$(sed -E 's/.* ([0-9.]+) Mrays in ([0-9.]+) s.*/\1 | \2/' <<<"$line")
      printf '| %s | %d | %s | %s | %s |\n' $s "$n" "$([ "$a" = 0 ] && echo off || echo "$a")" \
        "$(rmse "$f" "$ref")" "$rays"
    done
  done
done
