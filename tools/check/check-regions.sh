#!/usr/bin/env bash
# The check that the tests cannot be fooled: for each solution region, a
# scratch copy of the tree with only that region replaced by its stub (as the
# starter has it) must fail `make test-step N` of the step that introduces the
# region, and the image test of every later step whose picture uses it.
# Usage: tools/check/check-regions.sh [PATTERN]
#   PATTERN  only the regions whose "FILE FUNCTION" matches this grep -E pattern
# Exit 1 when a region can be stubbed without the failures it must cause, or
# when an exception below no longer holds. docs/testing-the-tests.md.
set -uo pipefail

usage() { echo "usage: tools/check/check-regions.sh [PATTERN]" >&2; exit 2; }
[ $# -le 1 ] || usage
pattern=${1:-}

. "$(dirname "$0")/scratch.sh"
scratch_top check-regions   # sets top and goes there
work=$top/build/check-regions
tree=$work/tree

# The image test(s), as Criterion names them in each step's test binary
# (suite::test, a grep -E pattern).
IMAGE_TESTS='^(image::step_matches_its_reference_image|reference_image::.*)$'

# Regions that cannot be stubbed alone: file-scope helpers that only another
# region of the same step calls. "STEP NAME=OTHER": stubbing NAME stubs OTHER
# of the same file too (what the starter does anyway).
TOGETHER=(
  "07 point_colour,pixel_sampled,colours_differ,at,square_mean=antialias_pixel"
  "08 area_incident=shade_area"
)

# Later steps that do not use a region: "STEP NAME STEPS reason". With the
# region stubbed, such a step must still pass its image test and render its
# picture byte for byte as the solution does; the check fails otherwise, so
# this table cannot rot.
EXCEPTIONS=(
  "01 film_sample 07,08 steps 07 and 08 place their own samples inside the pixel (pixel_sampled, or square_mean's lattice points) and never call film_sample"
  "02 sphere_hit_fill 03 step 03 draws each object in its flat colour: it needs the material hit (hit.material, set outside the region), not the point or the normal"
  "02 plane_hit_fill 03 step 03 draws each object in its flat colour: it needs the material hit (hit.material, set outside the region), not the point or the normal"
  "06 shade_trace 08 step 08's scene has no point light with a radius, so no light sphere for the camera to see"
)

now() { date +%s.%N; }
t_start=$(now)

# The regions to check: FILE FIRST LAST STEP NAME INDEX (INDEX: the region's
# rank in its file, for tools/check/stub.awk's only=).
all=$(tools/check/regions.sh list --tsv | awk -F'\t' '{ k[$1]++; print $1 "\t" $2 "\t" $3 "\t" $4 "\t" $5 "\t" k[$1] }') || {
  echo "check-regions: tools/check/regions.sh list failed" >&2; exit 1; }
selected=$(while IFS=$'\t' read -r file first last step name idx; do
  if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" <<<"$file $name"; then continue; fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$file" "$first" "$last" "$step" "$name" "$idx"
done <<<"$all")
[ -n "$selected" ] || { echo "check-regions: no region matches '${pattern}'" >&2; exit 1; }

# Each entry of the two tables must name regions of the tree.
is_region() { awk -F'\t' -v s="$1" -v n="$2" '$4 == s && $5 == n { found = 1 } END { exit !found }' <<<"$all"; }
for e in "${EXCEPTIONS[@]}"; do
  read -r es en esteps reason <<<"$e"
  is_region "$es" "$en" || {
    echo "check-regions: EXCEPTIONS names no region of the tree: step $es $en (renamed? update $0)" >&2; exit 1; }
done
for t in "${TOGETHER[@]}"; do
  read -r ts rest <<<"$t"
  is_region "$ts" "${rest%%=*}" && is_region "$ts" "${rest#*=}" || {
    echo "check-regions: TOGETHER names no region of the tree: step $ts $rest (renamed? update $0)" >&2; exit 1; }
done

# --------------------------------------------------------------- the tree
scratch_sync "$top" "$tree"
mkdir -p "$work/base" "$work/logs"
mapfile -t steps < <(scratch_steps "$tree")
step_dir() { local s; for s in "${steps[@]}"; do [ "${s%%-*}" = "$1" ] && echo "$s"; done; }

# test_step NN LOG: `make test-step NN` in the scratch tree, with a TAP report
# beside the log; returns make's exit status. A failing image test does not
# render the Phong terms (RT_TERMS=0, tests/terms.h): only its verdict counts.
# Every test runs (RT_CACHE=0): a reused result writes no TAP report.
test_step() {
  rm -f "$2.tap"
  RT_CACHE=0 RT_TERMS=0 CRITERION_OUTPUTS="tap:$2.tap" timeout 900 make -C "$tree" --no-print-directory \
    OPT="$SCRATCH_OPT" TEST_STEP_STRESS=0 test-step N="$1" >"$2" 2>&1
}

# render NN OUT: the step's default scene at its reference image's size.
render() {
  local s size
  s=$(step_dir "$1"); size=$(png_size "$tree/images/$s.png")
  (cd "$tree" && build/bin/"$s" --width "${size% *}" --height "${size#* }" --threads 2 \
     --quiet -o "$2") >/dev/null 2>&1
}

# The solution must pass first: otherwise every region "fails as expected".
echo "check-regions: building the solution in ${tree#$top/} and running every step's tests"
targets=$(for s in "${steps[@]}"; do echo "build/tests/$s"; done)
scratch_make "$tree" $targets || {
  echo "check-regions: the solution does not build:"; tail -n 20 "$tree/build/make.log"; exit 1; }
for s in "${steps[@]}"; do
  n=${s%%-*}
  if ! test_step "$n" "$work/logs/base-$n.log"; then
    echo "check-regions: the solution fails make test-step $n (${work#$top/}/logs/base-$n.log): fix it first"; exit 1
  fi
  [ -n "$(tap_tests "$work/logs/base-$n.log.tap" ok | grep -E "$IMAGE_TESTS")" ] || {
    echo "check-regions: step $n runs no image test matching $IMAGE_TESTS (renamed? update IMAGE_TESTS in $0)"; exit 1; }
  render "$n" "$work/base/$n.pfm" || { echo "check-regions: cannot render step $s"; exit 1; }
done
t_base=$(now)

# --------------------------------------------------------------- one region
# exception STEP NAME NN: the reason when step NN is an exception for the
# region, else nothing.
exception() {
  local e
  for e in "${EXCEPTIONS[@]}"; do
    read -r es en esteps reason <<<"$e"
    [ "$es" = "$1" ] && [ "$en" = "$2" ] && [[ ",$esteps," == *",$3,"* ]] && { echo "$reason"; return; }
  done
}

# companions FILE STEP NAME: the ranks of the regions of FILE stubbed with it.
companions() {
  local t other
  for t in "${TOGETHER[@]}"; do
    read -r ts rest <<<"$t"
    [ "$ts" = "$2" ] && [ "${rest%%=*}" = "$3" ] || continue
    other=${rest#*=}
    awk -F'\t' -v f="$1" -v s="$2" -v n="$other" '$1 == f && $4 == s && $5 == n { print $6 }' <<<"$all"
  done
}

# The steps a region reaches: its own folder's step, or for common/ every
# step from the one that introduces it on.
reached() {
  local file=$1 label=$2 s
  case "$file" in
    steps/*) s=${file#steps/}; echo "${s%%-*}" ;;
    *) for s in "${steps[@]}"; do [ $((10#${s%%-*})) -ge $((10#$label)) ] && echo "${s%%-*}"; done ;;
  esac
}

# check_step LABEL NAME NN TAG: one step of one stubbed region; prints the
# table cell, returns 1 when the step does not react as it must.
check_step() {
  local label=$1 name=$2 n=$3 tag=$4 log rc failed units img
  log=$work/logs/$tag-$n.log
  test_step "$n" "$log"; rc=$?
  failed=$(tap_tests "$log.tap" "not ok")
  img=$(grep -Eq "$IMAGE_TESTS" <<<"$failed" && echo 1 || echo 0)
  if [ -n "$(exception "$label" "$name" "$n")" ]; then
    # Not reached: the image test passes and the picture is the solution's.
    [ "$img" = 0 ] || { echo "$n:CHANGED"; return 1; }
    render "$n" "$work/stubbed.pfm" || { echo "$n:no-render"; return 1; }
    cmp -s "$work/stubbed.pfm" "$work/base/$n.pfm" || { echo "$n:CHANGED"; return 1; }
    echo "$n:same"; return 0
  fi
  # Unit tests that failed, the image tests and the savings (which warn and
  # fail nothing; docs/testing.md) left aside.
  units=$(grep -Ev "$IMAGE_TESTS" <<<"$failed" | grep -v '^saving::' | grep -c . || true)
  local cell="$n:" parts=()
  [ "$units" -gt 0 ] && parts+=("u$units")
  [ "$img" = 1 ] && parts+=(img)
  cell="$cell$(IFS=+; echo "${parts[*]}")"
  if [ $((10#$n)) -eq $((10#$label)) ]; then
    # The step that introduces the region: make test-step must fail.
    [ "$rc" -ne 0 ] || { echo "$n:PASSED"; return 1; }
    [ "$cell" = "$n:" ] && cell="${cell}exit$rc"
    echo "$cell"; return 0
  fi
  # A later step: its image test must fail.
  [ "$img" = 1 ] || { echo "$n:PASSED"; return 1; }
  echo "$cell"
}

printf '%-56s %-4s %-44s %s\n' region step "what each step's tests did" check
pass=0; fail=0
while IFS=$'\t' read -r file first last label name idx; do
  only=$idx
  for c in $(companions "$file" "$label" "$name"); do only="$only,$c"; done
  tag=$(echo "$file-$first" | tr '/.' '__')
  awk -v only="$only" -f "$top/tools/check/stub.awk" "$top/$file" >"$tree/$file"
  cells=(); ok=1
  if ! scratch_make "$tree" $targets; then
    cp "$tree/build/make.log" "$work/logs/$tag-build.log"
    cells=("does not build alone (${work#$top/}/logs/$tag-build.log): add it to TOGETHER")
    ok=0
  else
    for n in $(reached "$file" "$label"); do
      cell=$(check_step "$label" "$name" "$n" "$tag") || ok=0
      cells+=("$cell")
    done
  fi
  scratch_restore "$top" "$tree" "$file"
  what="$name"
  [ "$only" != "$idx" ] && what="$name (+$(companions "$file" "$label" "$name" | while read -r c; do awk -F'\t' -v f="$file" -v i="$c" '$1 == f && $6 == i { print $5 }' <<<"$all"; done))"
  if [ $ok = 1 ]; then verdict=PASS; pass=$((pass + 1)); else verdict=FAIL; fail=$((fail + 1)); fi
  printf '%-56s %-4s %-44s %s\n' "$file:$first $what" "$label" "${cells[*]}" "$verdict"
done <<<"$selected"

# Leave the scratch tree built as the solution (the next run starts from it).
scratch_make "$tree" $targets || true
t_end=$(now)
echo
echo "Legend: NN:u3+img = make test-step NN failed 3 unit tests and the image test;"
echo "NN:same = a step the region does not reach (EXCEPTIONS in tools/check/check-regions.sh):"
echo "its image test passes and its picture is the solution's, byte for byte."
echo "FAIL cells: NN:PASSED (the step passed with the region stubbed), NN:CHANGED"
echo "(an exception whose picture changed: update EXCEPTIONS)."
for e in "${EXCEPTIONS[@]}"; do
  read -r es en esteps reason <<<"$e"
  echo "  exception: step $es $en, steps $esteps: $reason"
done
awk -v r=$((pass + fail)) -v p=$pass -v f=$fail -v a="$t_start" -v b="$t_base" -v e="$t_end" \
  'BEGIN { printf "check-regions: %d regions, %d PASS, %d FAIL (%.0f s: the solution %.0f s, the regions %.0f s)\n", r, p, f, e - a, b - a, e - b }'
[ $fail -eq 0 ]
