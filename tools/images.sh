#!/usr/bin/env bash
# Write (or check) the reference images images/NN-name.png: each step's
# default scene rendered with the options of the image test
# (tests/image_test.c: --width W --height H --threads 2 --quiet, and the
# options in images/NN-name.args when that file exists), at 320x240, 01-film
# at its scene's 256x128.
# Usage: tools/images.sh write|check BUILD STEP...   (make images, make check-images)
# check renders into a temporary folder and fails when any pixel of a
# reference differs from the render, by any amount.
set -uo pipefail
mode=$1 build=$2; shift 2
size() { [ "$1" = 01-film ] && echo "--width 256 --height 128" || echo "--width 320 --height 240"; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/images.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
stale=0
for s in "$@"; do
  out=images/$s.png
  [ "$mode" = check ] && out=$tmp/$s.png
  args=$(cat "images/$s.args" 2>/dev/null || true)
  # What a step says it ignores (the lights, in steps 02-03) is no news here.
  # shellcheck disable=SC2046,SC2086  # options and their values, split on spaces
  "$build/bin/$s" $(size "$s") --threads 2 --quiet $args -o "$out" 2>"$tmp/err" || {
    cat "$tmp/err" >&2; exit 1; }
  [ "$mode" = check ] || continue
  if [ ! -f "images/$s.png" ]; then
    echo "missing: images/$s.png (run 'make images')"; stale=1; continue
  fi
  why=$("$build/bin/imgcmp" "images/$s.png" "$out")
  case $? in
    0) ;;
    1) echo "stale: images/$s.png: $why (run 'make images' if the change is meant)"; stale=1 ;;
    *) echo "images: images/$s.png: ${why:-cannot compare}"; stale=1 ;;
  esac
done
[ "$mode" = write ] && echo "wrote images/ for: $*"
exit $stale
