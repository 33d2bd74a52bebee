#!/usr/bin/env bash
# The reference traces (tests/traces/pixels lists the pixels; docs/tracing.md,
# "Reference traces").
#   tools/traces.sh write BUILD STEP...        rewrite tests/traces/STEP/X_Y.json
#   tools/traces.sh compare BUILD STEP [X Y]   the step's traces against them,
#                                              the first differing line of each
# Exit status: 0 all agree (or written), 1 some trace differs, 2 bad usage.
set -uo pipefail
mode=${1:-}; build=${2:-}; step=${3:-}
list=tests/traces/pixels
[ -n "$step" ] && [ -r "$list" ] || { echo "usage: tools/traces.sh write|compare BUILD STEP [X Y]" >&2; exit 2; }

# The lines of the pixel list for one step: "X Y|OPTIONS|WHAT".
pixels() {
  grep -v '^#' "$list" | awk -F'|' -v s="$1" '{gsub(/^ +| +$/, "", $1)} $1 == s {
    gsub(/^ +| +$/, "", $2); gsub(/^ +| +$/, "", $3); gsub(/^ +| +$/, "", $4)
    print $2 "|" $3 "|" $4 }'
}

if [ "$mode" = write ]; then
  shift 2
  for step in "$@"; do
    rm -f tests/traces/"$step"/*.json
    mkdir -p tests/traces/"$step"
    while IFS='|' read -r xy options what; do
      read -r x y <<<"$xy"
      # shellcheck disable=SC2086 # the options are words
      "$build/bin/$step" $options --trace "$x" "$y" --trace-format json \
        > "tests/traces/$step/${x}_$y.json" || exit 1
    done < <(pixels "$step")
  done
  exit 0
fi

[ "$mode" = compare ] || { echo "tools/traces.sh: unknown mode '$mode'" >&2; exit 2; }
want="${4:-} ${5:-}"
status=0; found=0
while IFS='|' read -r xy options what; do
  read -r x y <<<"$xy"
  [ "$want" = " " ] || [ "$want" = "$x $y" ] || continue
  found=1
  "$build/bin/trace-diff" "$build/bin/$step" "tests/traces/$step/${x}_$y.json" "$what" || status=1
done < <(pixels "$step")
if [ "$found" = 0 ]; then
  echo "tools/traces.sh: no reference trace of $step at ($want); the pixels with one:"
  pixels "$step" | awk -F'|' '{print "  " $1 "   " $3}'
  exit 2
fi
exit $status
