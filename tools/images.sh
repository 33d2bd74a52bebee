#!/usr/bin/env bash
# Write (or check) the reference images images/NN-name.png: each step's
# default scene rendered with the options of the image test
# (tests/image_test.c: --width W --height H --threads 2 --quiet, and the
# options in images/NN-name.args when that file exists), at 320x240, 01-film
# at its scene's 256x128. Steps 04-08 also get their Phong terms, each drawn
# alone (--aov TERM): images/NN-name.TERM.png, which the image test compares
# when the picture is wrong (tests/terms.h).
# Usage: tools/images.sh write|check BUILD STEP...   (make images, make check-images)
# check renders into a temporary folder and fails when any pixel of a
# reference differs from the render, by any amount.
set -uo pipefail
mode=$1 build=$2; shift 2
size() { [ "$1" = 01-film ] && echo "--width 256 --height 128" || echo "--width 320 --height 240"; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/images.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
terms() { case $1 in 0[4-8]-*) echo ambient diffuse specular ;; esac; }
stale=0
for s in "$@"; do
 for term in "" $(terms "$s"); do
  name=$s${term:+.$term}
  out=images/$name.png
  [ "$mode" = check ] && out=$tmp/$name.png
  args=$(cat "images/$s.args" 2>/dev/null || true)
  # What a step says it ignores (the lights, in steps 02-03) is no news here.
  # shellcheck disable=SC2046,SC2086  # options and their values, split on spaces
  "$build/bin/$s" $(size "$s") --threads 2 --quiet $args ${term:+--aov $term} -o "$out" \
    2>"$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
  [ "$mode" = check ] || continue
  if [ ! -f "images/$name.png" ]; then
    echo "missing: images/$name.png (run 'make images')"; stale=1; continue
  fi
  why=$("$build/bin/imgcmp" "images/$name.png" "$out")
  case $? in
    0) ;;
    1) echo "stale: images/$name.png: $why (run 'make images' if the change is meant)"; stale=1 ;;
    *) echo "images: images/$name.png: ${why:-cannot compare}"; stale=1 ;;
  esac
 done
done
[ "$mode" = write ] && echo "wrote images/ for: $*"
exit $stale
