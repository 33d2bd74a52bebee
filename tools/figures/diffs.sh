#!/usr/bin/env bash
# Write (or check) docs/diffs/NN-name.diff: the lesson of each step. Its
# folder against the previous step's, then every file that holds a solution
# region, as a student's tree has it with the steps before NN solved against
# the same with step NN solved too (tools/check/stub.awk, as make starter writes
# them): the regions the step adds, wherever they live.
# Usage: tools/figures/diffs.sh write|check STEP...
# write (make regen) rewrites a diff only when its text changes and prints
# "regen: wrote FILE"; check fails when it would.
set -uo pipefail
mode=$1; shift
mkdir -p docs/diffs
declare -A step_name
for s in steps/[0-9][0-9]-*/; do s=${s%/}; s=${s#steps/}; step_name[${s%%-*}]=$s; done
names=$(for k in "${!step_name[@]}"; do printf '%s=%s ' "$k" "${step_name[$k]}"; done)
region_files=$(grep -l -r --include='*.[ch]' 'BEGIN SOLUTION' common steps | sort)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/diffs.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prev=""; stale=0
for s in "$@"; do
  if [ -n "$prev" ]; then
    out=docs/diffs/$s.diff
    n=$((10#${s%%-*}))
    # File times are dropped from the headers: a fresh clone must match.
    new=$(diff -ruN "steps/$prev" "steps/$s" | sed -E 's/^((---|[+][+][+]) [^[:space:]]+)[[:space:]].*/\1/'
          for f in $region_files; do
            mkdir -p "$tmp/a/$(dirname "$f")" "$tmp/b/$(dirname "$f")"
            awk -v keep_below=$n -v names="$names" -f tools/check/stub.awk "$f" > "$tmp/a/$f"
            awk -v keep_below=$((n + 1)) -v names="$names" -f tools/check/stub.awk "$f" > "$tmp/b/$f"
            (cd "$tmp" && diff -u --label "a/$f" --label "b/$f" "a/$f" "b/$f")
          done)
    if [ "$(printf '%s\n' "$new")" != "$(cat "$out" 2>/dev/null)" ]; then
      if [ "$mode" = write ]; then
        printf '%s\n' "$new" > "$out.tmp" && mv "$out.tmp" "$out" && echo "regen: wrote $out"
      else
        echo "stale: $out (run make regen)"; stale=1
      fi
    fi
  fi
  prev=$s
done
exit $stale
