#!/bin/sh
# The speed pack draws the pictures the plain program draws, byte for byte:
# every step (01-08) with each sampler (center grid random jitter sobol) and
# adaptive sampling off and at the step's default, rendered to .pfm by the
# default build and by a FAST=0 build, compared with cmp.
#   BUILD=build/nofast make FAST=0 && bench/same-pictures.sh [FAST_BIN NOFAST_BIN [ARGS...]]
# FAST_BIN, NOFAST_BIN: the two bin folders (build/bin, build/nofast/bin);
# ARGS: more options for every render (e.g. --width 200 --height 150).
# Prints one line per difference and a count; exit status 1 when any differ.
fast=${1:-build/bin}
plain=${2:-build/nofast/bin}
[ $# -ge 2 ] && shift 2
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
runs=0 differ=0
for bin in "$fast"/0[1-8]-*; do
  step=$(basename "$bin")
  for sampler in center grid random jitter sobol; do
    for adaptive in 0 default; do
      opt="--sampler $sampler"
      [ "$adaptive" = 0 ] && opt="$opt --adaptive 0"
      rm -f "$tmp/a.pfm" "$tmp/b.pfm"
      # shellcheck disable=SC2086 # opt holds several words
      "$bin" -q $opt "$@" -o "$tmp/a.pfm" 2>"$tmp/a.err"
      # shellcheck disable=SC2086
      "$plain/$step" -q $opt "$@" -o "$tmp/b.pfm" 2>"$tmp/b.err"
      runs=$((runs + 1))
      if [ ! -s "$tmp/a.pfm" ]; then
        echo "no picture: $step $opt $*: $(head -1 "$tmp/a.err")"
        differ=$((differ + 1))
      elif ! cmp -s "$tmp/a.pfm" "$tmp/b.pfm"; then
        echo "differ: $step $opt $*"
        differ=$((differ + 1))
      fi
    done
  done
done
echo "same-pictures: $runs renders compared, $differ differ"
[ "$differ" -eq 0 ]
