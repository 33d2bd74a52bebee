#!/usr/bin/env bash
# The reference traces: the pixels of each step's manifest (TRACE_X_Y lines
# of steps/STEP/step.mk, rendered with its TRACE_ARGS), traced by the
# solution into tests/traces/STEP/X_Y.json (docs/tracing.md, "Reference
# traces").
#   tools/figures/traces.sh write BUILD STEP...        make regen: rewrite a trace only when
#                                              it is missing, was made with other
#                                              options, or differs beyond trace-diff's
#                                              tolerance; remove the traces of pixels
#                                              the manifest no longer lists
#   tools/figures/traces.sh compare BUILD STEP [X Y]   the step's traces against them,
#                                              the first differing line of each
# write prints "regen: wrote FILE" for each file it writes or removes.
# Exit status: 0 all agree (or written), 1 some trace differs, 2 bad usage.
set -uo pipefail
mode=${1:-}; build=${2:-}; step=${3:-}
[ -n "$step" ] || { echo "usage: tools/figures/traces.sh write|compare BUILD STEP [X Y]" >&2; exit 2; }
here=$(dirname "$0")

# The step's pixels: "X Y|OPTIONS|WHAT" a line.
pixels() { "$here/../build/manifest.sh" traces "$1"; }

if [ "$mode" = write ]; then
  shift 2
  for step in "$@"; do
    list=$(pixels "$step") || exit 1
    dir=tests/traces/$step
    mkdir -p "$dir"
    keep=" "
    while IFS='|' read -r xy options what; do
      [ -n "$xy" ] || continue
      read -r x y <<<"$xy"
      f=$dir/${x}_$y.json; keep="$keep${x}_$y.json "
      # The options it was made with, as the trace's header holds them.
      made=$(sed -n '1s/.*"args": "\([^"]*\)".*/\1/p' "$f" 2>/dev/null)
      if [ -f "$f" ] && [ "$made" = "$options" ] &&
         "$build/bin/trace-diff" "$build/bin/$step" "$f" "$what" > /dev/null 2>&1; then
        continue
      fi
      # shellcheck disable=SC2086 # the options are words
      "$build/bin/$step" $options --trace "$x" "$y" --trace-format json > "$f.tmp" &&
        mv "$f.tmp" "$f" || { rm -f "$f.tmp"; echo "traces: $step --trace $x $y failed" >&2; exit 1; }
      echo "regen: wrote $f"
    done <<<"$list"
    for f in "$dir"/*.json; do
      [ -e "$f" ] || continue
      case $keep in *" ${f##*/} "*) ;; *) rm -f "$f"; echo "regen: removed $f (no TRACE_ line for it in steps/$step/step.mk)" ;; esac
    done
  done
  exit 0
fi

[ "$mode" = compare ] || { echo "tools/figures/traces.sh: unknown mode '$mode'" >&2; exit 2; }
want="${4:-} ${5:-}"
status=0; found=0
while IFS='|' read -r xy options what; do
  read -r x y <<<"$xy"
  [ "$want" = " " ] || [ "$want" = "$x $y" ] || continue
  found=1
  f=tests/traces/$step/${x}_$y.json
  if [ ! -f "$f" ]; then echo "missing: $f (run make regen)"; status=1; continue; fi
  made=$(sed -n '1s/.*"args": "\([^"]*\)".*/\1/p' "$f")
  if [ "$made" != "$options" ]; then
    echo "stale: $f was traced with '$made', steps/$step/step.mk says '$options' (run make regen)"
    status=1; continue
  fi
  "$build/bin/trace-diff" "$build/bin/$step" "$f" "$what" || status=1
done < <(pixels "$step")
if [ "$found" = 0 ]; then
  echo "tools/figures/traces.sh: no reference trace of $step at ($want); the pixels with one:"
  pixels "$step" | awk -F'|' '{print "  " $1 "   " $3}'
  exit 2
fi
exit $status
