#!/usr/bin/env bash
# tests/diagnoses.tsv: the signature of each known mistake (docs/mutants.md,
# "Diagnosis"). Each bug of tools/check/mutants/ is applied alone to a scratch copy
# of the tree and built; its own step's tests run (the step's test binary and
# the stress tests of that step, as make test-step runs them), and every
# failing check's signature (tests/results.awk) is recorded with the mutant's
# "what:" line. tests/run.sh names the mistake on a verdict line whose check
# and signature are in the table.
# Usage: tools/check/diagnoses.sh [write] [PATTERN]  the table (written only when
#                                               its content changes); PATTERN
#                                               (grep -E on the IDs): those
#                                               mutants alone, to build/diagnoses/
#        tools/check/diagnoses.sh check              exit 1 when the table is stale
#        tools/check/diagnoses.sh measure [PATTERN]  every mutant, bugs and correct
#                                               alternatives, in the student's
#                                               build (make's flags): is it
#                                               caught at its step, is its own
#                                               mistake named; the table in
#                                               build/diagnoses/measure.md
set -uo pipefail

usage() { echo "usage: tools/check/diagnoses.sh [write|check|measure] [PATTERN]" >&2; exit 2; }
mode=write
case "${1:-}" in write|check|measure) mode=$1; shift ;; esac
[ $# -le 1 ] || usage
pattern=${1:-}

. "$(dirname "$0")/scratch.sh"
scratch_top diagnoses
table=tests/diagnoses.tsv

# What the signatures depend on: the bugs (tools/check/mutants/, kind: bug; the
# correct alternatives give none), the files they change, the tests (the
# tracer's excepted: no step's test binary holds them) and the verdict
# printer that forms the signature (tests/results.awk), the reference images
# and the scenes. Their hash heads the table; a change to any of them makes
# it stale.
inputs_hash() {
  local bugs globs
  bugs=$(grep -l '^kind:[ \t]*bug[ \t]*$' tools/check/mutants/*.mut)
  # shellcheck disable=SC2086
  globs=$(sed -n 's/^file:[ \t]*//p' $bugs | sort -u)
  # shellcheck disable=SC2086
  { ls $bugs; for g in $globs; do ls $g 2>/dev/null; done
    ls tests/*.c tests/*.h tests/results.awk images/* scenes/* 2>/dev/null
  } | grep -v '^tests/test_trace\.c$' | sort -u | while IFS= read -r f; do
    [ -f "$f" ] && printf '%s %s\n' "$(sha1sum < "$f" | cut -c1-40)" "$f"
  done | sha1sum | cut -c1-40
}

if [ $mode = check ]; then
  want=$(inputs_hash)
  have=$(sed -n 's/^# inputs: //p' "$table" 2>/dev/null)
  if [ "$want" != "$have" ]; then
    echo "check-diagnoses: $table is stale (the mutants, the code they change or the tests changed): run make regen (or make diagnoses)"
    exit 1
  fi
  echo "check-diagnoses: $table is up to date"
  exit 0
fi

now() { date +%s; }
t_start=$(now)
work=$top/build/diagnoses
if [ $mode = measure ]; then tree=$work/measure-tree; opt=(); else tree=$work/tree; opt=(OPT="$SCRATCH_OPT"); fi
mkdir -p "$work/logs" "$work/sig"

kinds='bug'
[ $mode = measure ] && kinds='bug|alternative|alternative-unrefined'
mapfile -t mutants < <(tools/check/mutate.sh --list |
  awk -F'\t' -v p="$pattern" -v k="^($kinds)\$" '(p == "" || $1 ~ p) && $3 ~ k')
[ ${#mutants[@]} -gt 0 ] || { echo "diagnoses: no mutant matches '$pattern'" >&2; exit 1; }
scratch_sync "$top" "$tree"
# The measure runs the table being measured.
[ $mode = measure ] && cp "$table" "$tree/$table"

# targets S: what make test-step S builds (tests/run.sh then runs them).
targets() {
  local name
  name=$(scratch_step_name "$tree" "$1")
  echo "build/tests/$name build/tests/stress"
  case $1 in 05|06|07|08) echo "build/bin/04-phong build/bin/05-shadows build/bin/mistakes" ;; esac
}
# run_step S SIGFILE LOG: step S's tests, then, when they pass, its own
# stress tests (the earlier steps' do not run the mistake: it is in step S's
# code; a mistake the step's tests catch is named on their lines); 0 when
# they pass.
run_step() {
  local name
  name=$(scratch_step_name "$tree" "$1")
  (cd "$tree" && RT_CACHE=0 RT_STRESS_ONLY=$1 RT_SIGNATURES=$2 RESULTS_DIR=$work/results \
     timeout 900 tests/run.sh "build/tests/$name" &&
   RT_CACHE=0 RT_STRESS_ONLY=$1 RT_SIGNATURES=$2 RESULTS_DIR=$work/results \
     timeout 900 tests/run.sh build/tests/stress) >"$3" 2>&1
}
build() {
  make -C "$tree" --no-print-directory -j"${JOBS:-2}" "${opt[@]}" "$@" >"$tree/build/make.log" 2>&1
}

mkdir -p "$tree/build"
echo "diagnoses: building the solution in ${tree#$top/}"
steps=$(for m in "${mutants[@]}"; do IFS=$'\t' read -r _ s _ _ <<<"$m"; echo "$s"; done | sort -u)
# shellcheck disable=SC2046
build $(for s in $steps; do targets "$s"; done) || {
  echo "diagnoses: the solution does not build:"; tail -n 20 "$tree/build/make.log"; exit 1; }
for s in $steps; do
  : >"$work/sig/base-$s"
  run_step "$s" "$work/sig/base-$s" "$work/logs/base-$s.log" || {
    echo "diagnoses: the solution fails step $s's tests (${work#$top/}/logs/base-$s.log): fix it first"; exit 1; }
done

rows=$work/rows.tsv
: >"$rows"
results=$work/measure.tsv
: >"$results"
errors=0
for m in "${mutants[@]}"; do
  IFS=$'\t' read -r id step kind what <<<"$m"
  if ! files=$(tools/check/mutate.sh "$id" "$tree" 2>"$work/logs/$id.apply"); then
    cat "$work/logs/$id.apply"; errors=$((errors + 1)); continue
  fi
  sig=$work/sig/$id
  : >"$sig"
  # shellcheck disable=SC2046
  if ! build $(targets "$step"); then
    echo "diagnoses: $id does not build"; errors=$((errors + 1))
  else
    run_step "$step" "$sig" "$work/logs/$id.log"
    # CHECK SIGNATURE MUTANT STEP WHAT
    awk -F'\t' -v id="$id" -v step="$step" -v what="$what" \
      '{ printf "%s\t%s\t%s\t%s\t%s\n", $2, $3, id, step, what }' "$sig" >>"$rows"
    if [ $mode = measure ]; then
      # Caught (a FAIL line), and the FAIL lines' diagnoses.
      caught=$(grep -c '^FAIL ' "$work/logs/$id.log")
      own=$(grep '^FAIL .*looks like ' "$work/logs/$id.log" | sed 's/.*looks like //' | grep -cF "$what")
      any=$(grep '^FAIL ' "$work/logs/$id.log" | grep -c 'looks like ')
      printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$id" "$kind" "$caught" "$own" "$any" "$what" >>"$results"
      printf '%-34s %-22s FAIL lines %s, naming it %s, any diagnosis %s\n' "$id" "$kind" "$caught" "$own" "$any"
    else
      printf '%-34s %s failing check(s)\n' "$id" "$(wc -l < "$sig")"
    fi
  fi
  scratch_restore "$top" "$tree" $files
done

if [ $mode = measure ]; then
  {
    echo "| mutant | kind | FAIL lines | naming its mistake | any diagnosis |"
    echo "|---|---|---|---|---|"
    awk -F'\t' '{ printf "| `%s` | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5 }' "$results"
    echo
    awk -F'\t' '$2 == "bug" && $3 > 0 { c++; if ($4 > 0) n++ }
                $2 != "bug" { a++; if ($5 > 0) d++ }
                END { printf "Bugs caught at their step: %d; their verdict names their mistake: %d (%.0f %%).\n", c, n, c ? 100 * n / c : 0
                      printf "Correct alternatives: %d; given a diagnosis: %d.\n", a, d }' "$results"
  } >"$work/measure.md"
  tail -n 2 "$work/measure.md"
  echo "diagnoses: wrote ${work#$top/}/measure.md ($(( $(now) - t_start )) s)"
  exit $((errors > 0))
fi

out=$table
[ -n "$pattern" ] && out=$work/diagnoses.tsv
{
  echo "# The known mistakes' signatures (docs/mutants.md, \"Diagnosis\"): CHECK, SIGNATURE,"
  echo "# MUTANT, STEP, WHAT, tab-separated. Generated by make diagnoses (tools/check/diagnoses.sh)"
  echo "# from tools/check/mutants/; do not edit."
  echo "# inputs: $(inputs_hash)"
  sort -u "$rows"
} >"$work/table.new"
if cmp -s "$work/table.new" "$out"; then
  echo "diagnoses: ${out#$top/} unchanged ($(( $(now) - t_start )) s)"
else
  mv "$work/table.new" "$out"
  echo "diagnoses: rewrote ${out#$top/}: $(grep -vc '^#' "$out") signatures of ${#mutants[@]} mutants ($(( $(now) - t_start )) s)"
fi
exit $((errors > 0))
