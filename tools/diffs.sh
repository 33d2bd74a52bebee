#!/usr/bin/env bash
# Write (or check) docs/diffs/NN-name.diff: each step's folder against the
# previous step's, the lesson of that step. Usage: tools/diffs.sh write|check STEP...
set -uo pipefail
mode=$1; shift
mkdir -p docs/diffs
prev=""; stale=0
for s in "$@"; do
  if [ -n "$prev" ]; then
    out=docs/diffs/$s.diff
    # File times are dropped from the headers: a fresh clone must match.
    new=$(diff -ruN "steps/$prev" "steps/$s" | sed -E 's/^((---|[+][+][+]) [^[:space:]]+)[[:space:]].*/\1/')
    if [ "$mode" = write ]; then
      printf '%s\n' "$new" > "$out"
    elif [ "$(printf '%s\n' "$new")" != "$(cat "$out" 2>/dev/null)" ]; then
      echo "stale: $out (run 'make diffs')"; stale=1
    fi
  fi
  prev=$s
done
[ "$mode" = write ] && echo "wrote docs/diffs/ for: $*"
exit $stale
