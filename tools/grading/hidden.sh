#!/usr/bin/env bash
# The hidden scenes' plan (docs/grading.md, "Hidden scenes"): each file
# HIDDEN/NN-name.scene is graded at step NN, against the instructor's
# solution's render of it, cached by content (the scene, the solution's
# binary, the options). Steps with noise (GRADE_NOISY_STEPS, default 07 08)
# get GRADE_SEEDS solution renders (seeds 1..K, default 8) and the student
# renders with seed K+1; the others one render each, seed 1.
# Usage: tools/grading/hidden.sh BASE HIDDEN CACHE > PLAN
# PLAN lines: CHECK STEP SCENE MODE SEED COST REFS (tab-separated; COST the
# solution's render in thread-seconds; REFS space-separated .pfm paths).
set -euo pipefail

[ $# = 3 ] || { echo "usage: tools/grading/hidden.sh BASE HIDDEN CACHE" >&2; exit 2; }
base=$1 hidden=$2 cache=$3/hidden
seeds=${GRADE_SEEDS:-8}
threads=${GRADE_THREADS:-$(nproc)}
[ -d "$hidden" ] || { echo "grade: HIDDEN=$hidden is not a folder" >&2; exit 1; }
mkdir -p "$cache"

shopt -s nullglob
for scene in "$hidden"/*.scene; do
  file=${scene##*/}
  nn=${file%%-*}
  step=$(grep -x "$nn-.*" "$base/steps.txt" || true)
  if ! [[ "$nn" =~ ^[0-9][0-9]$ ]] || [ -z "$step" ]; then
    echo "grade: hidden scene $file ignored: its name must start with a step number (04-mirror.scene)" >&2
    continue
  fi
  stem=${file#"$nn"-}; stem=${stem%.scene}
  bin=$base/solved/build/bin/$step
  key=$( { sha1sum <"$scene"; sha1sum <"$bin"; } | sha1sum | cut -c1-16)
  cp "$scene" "$cache/$key.scene"
  if [[ " ${GRADE_NOISY_STEPS:-07 08} " == *" $nn "* ]]; then
    mode=noise; first=1; last=$seeds; student_seed=$((seeds + 1))
  else
    mode=exact; first=1; last=1; student_seed=1
  fi
  refs=()
  for ((k = first; k <= last; k++)); do
    ref=$cache/$key-seed$k.pfm
    if [ ! -f "$ref" ]; then
      t0=$(date +%s.%N)
      "$bin" --scene "$cache/$key.scene" --threads "$threads" --seed "$k" --quiet -o "$ref.tmp.pfm" || {
        echo "grade: the solution cannot render hidden scene $scene (step $step)" >&2; exit 1; }
      awk -v a="$t0" -v b="$(date +%s.%N)" -v n="$threads" 'BEGIN { printf "%.3f\n", (b - a) * n }' >"$ref.cost"
      mv "$ref.tmp.pfm" "$ref"
    fi
    refs+=("$ref")
  done
  printf '%s/hidden/%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$step" "$stem" "$step" "$cache/$key.scene" "$mode" \
    "$student_seed" "$(cat "${refs[0]}.cost")" "${refs[*]}"
done
