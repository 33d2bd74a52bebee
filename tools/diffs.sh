#!/usr/bin/env bash
# Write (or check) docs/diffs/NN-name.diff: each step's folder against the
# previous step's, the lesson of that step. Usage: tools/diffs.sh write|check STEP...
# write (make regen) rewrites a diff only when its text changes and prints
# "regen: wrote FILE"; check fails when it would.
set -uo pipefail
mode=$1; shift
mkdir -p docs/diffs
prev=""; stale=0
for s in "$@"; do
  if [ -n "$prev" ]; then
    out=docs/diffs/$s.diff
    # File times are dropped from the headers: a fresh clone must match.
    new=$(diff -ruN "steps/$prev" "steps/$s" | sed -E 's/^((---|[+][+][+]) [^[:space:]]+)[[:space:]].*/\1/')
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
