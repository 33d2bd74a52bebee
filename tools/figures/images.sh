#!/usr/bin/env bash
# The reference images images/NN-name.png: each step's default scene rendered
# as its manifest says (steps/NN-name/step.mk: IMAGE_SIZE, IMAGE_ARGS, and
# --threads 2 --quiet, the image test's command line), and each Phong term of
# IMAGE_TERMS drawn alone (--aov TERM): images/NN-name.TERM.png, which the
# image test compares when the picture is wrong (tests/terms.h).
# Usage: tools/figures/images.sh write|check BUILD STEP...   (make regen, make check-images)
# Both render into a temporary folder. write rewrites a reference only when
# some pixel differs (any channel, by any amount: check's own tolerance),
# through the one writer of kept pictures (tools/loop/imgcmp.c --put), and prints
# "regen: wrote FILE (why)"; check fails when it would write.
set -uo pipefail
mode=$1 build=$2; shift 2
here=$(dirname "$0")
tmp=$(mktemp -d "${TMPDIR:-/tmp}/images.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
stale=0
for s in "$@"; do
 size=$("$here/../build/manifest.sh" get "$s" IMAGE_SIZE) && args=$("$here/../build/manifest.sh" get "$s" IMAGE_ARGS) &&
   terms=$("$here/../build/manifest.sh" get "$s" IMAGE_TERMS) || exit 1
 for term in "" $terms; do
  name=$s${term:+.$term}
  out=$tmp/$name.png
  # What a step says it ignores (the lights, in steps 02-03) is no news here.
  # shellcheck disable=SC2086  # options and their values, split on spaces
  "$build/bin/$s" --width "${size% *}" --height "${size#* }" --threads 2 --quiet $args \
    ${term:+--aov $term} -o "$out" 2>"$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
  if [ "$mode" = write ]; then
    "$build/bin/imgcmp" --put "images/$name.png" "$out" || exit 1
    continue
  fi
  if [ ! -f "images/$name.png" ]; then
    echo "missing: images/$name.png (run make regen)"; stale=1; continue
  fi
  why=$("$build/bin/imgcmp" "images/$name.png" "$out")
  case $? in
    0) ;;
    1) echo "stale: images/$name.png: $why (run make regen if the change is meant)"; stale=1 ;;
    *) echo "stale: images/$name.png: ${why:-cannot compare} (run make regen if the change is meant)"; stale=1 ;;
  esac
 done
done
exit $stale
