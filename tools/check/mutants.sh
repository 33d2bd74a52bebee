#!/usr/bin/env bash
# The mutation run: each mutant of tools/check/mutants/ (a realistic student bug, or
# a correct alternative) applied alone to a scratch copy of the tree, built,
# and put through `make test-step K` for every step K and the stress tests.
# Usage: tools/check/mutants.sh [--check] [PATTERN]
#   --check   only apply every mutant to a scratch copy (do they still match
#             the code?), no build
#   PATTERN   only the mutants whose ID matches this grep -E pattern
# Writes docs/mutants.md when it runs every mutant, else build/mutants/mutants.md.
# Exit 1 when a mutant no longer applies or does not build, or when a correct
# alternative fails a test. docs/testing-the-tests.md.
set -uo pipefail

usage() { echo "usage: tools/check/mutants.sh [--check] [PATTERN]" >&2; exit 2; }
check_only=0
[ "${1:-}" = --check ] && { check_only=1; shift; }
[ $# -le 1 ] || usage
pattern=${1:-}

. "$(dirname "$0")/scratch.sh"
scratch_top mutants   # sets top and goes there
work=$top/build/mutants
tree=$work/tree

now() { date +%s.%N; }
t_start=$(now)

mapfile -t mutants < <(tools/check/mutate.sh --list | awk -F'\t' -v p="$pattern" 'p == "" || $1 ~ p')
[ ${#mutants[@]} -gt 0 ] || { echo "mutants: no mutant matches '$pattern'" >&2; exit 1; }
scratch_sync "$top" "$tree"
mkdir -p "$work/logs"

# --check: does every mutant still apply?
if [ $check_only = 1 ]; then
  bad=0
  for m in "${mutants[@]}"; do
    id=${m%%$'\t'*}
    if files=$(tools/check/mutate.sh "$id" "$tree" 2>"$work/logs/$id.apply"); then
      scratch_restore "$top" "$tree" $files
    else
      cat "$work/logs/$id.apply"; bad=1
    fi
  done
  [ $bad = 0 ] && echo "mutants: all ${#mutants[@]} mutants apply to the tree"
  exit $bad
fi

mapfile -t steps < <(scratch_steps "$tree")
# The stress tests' binaries, as the Makefile's `stress` rule names them.
stress_bins=$(sed -n 's/^stress: *//p' Makefile | tr ' ' '\n' | sed -n 's/^\$(BUILD)\//build\//p')
[ -n "$stress_bins" ] || { echo "mutants: no 'stress:' rule in the Makefile" >&2; exit 1; }
targets="$(printf 'build/tests/%s ' "${steps[@]}") build/tests/stress $stress_bins"

# What a step's tests run: its test binary and its program (the image and CLI
# tests call build/bin/STEP). When a mutant leaves both byte for byte the
# solution's, the step's verdict is the solution's and the step is not re-run.
fingerprint() {
  local n=$1 s
  if [ "$n" = stress ]; then
    (cd "$tree" && cat build/tests/stress $stress_bins | sha1sum)
  else
    for s in "${steps[@]}"; do [ "${s%%-*}" = "$n" ] && (cd "$tree" && cat "build/tests/$s" "build/bin/$s" | sha1sum); done
  fi
}

# run_check N LOG: make test-step N (or the stress tests); 0 when it passes.
run_check() {
  if [ "$1" = stress ]; then
    timeout 900 make -C "$tree" --no-print-directory OPT="$SCRATCH_OPT" stress >"$2" 2>&1
  else
    timeout 900 make -C "$tree" --no-print-directory OPT="$SCRATCH_OPT" TEST_STEP_STRESS=0 \
      test-step N="$1" >"$2" 2>&1
  fi
}

checks=$(for s in "${steps[@]}"; do echo "${s%%-*}"; done; echo stress)
echo "mutants: building the solution in ${tree#$top/} and running every step's tests"
scratch_make "$tree" $targets || {
  echo "mutants: the solution does not build:"; tail -n 20 "$tree/build/make.log"; exit 1; }
declare -A base
for c in $checks; do
  run_check "$c" "$work/logs/base-$c.log" || {
    echo "mutants: the solution fails $([ "$c" = stress ] && echo "make stress" || echo "make test-step $c")" \
         "(${work#$top/}/logs/base-$c.log): fix it first"; exit 1; }
  base[$c]=$(fingerprint "$c")
done
t_base=$(now)

# One line per mutant in results.tsv: ID STEP KIND CAUGHT RAN STATUS WHAT, where
# CAUGHT and RAN are the checks (NN or stress) that failed and that ran.
results=$work/results.tsv
: >"$results"
errors=0
for m in "${mutants[@]}"; do
  IFS=$'\t' read -r id step kind what <<<"$m"
  t0=$(now)
  if ! files=$(tools/check/mutate.sh "$id" "$tree" 2>"$work/logs/$id.apply"); then
    cat "$work/logs/$id.apply"; errors=$((errors + 1))
    printf '%s\t%s\t%s\t\t\tSTALE\t%s\n' "$id" "$step" "$kind" "$what" >>"$results"; continue
  fi
  caught=() ran=() status=ok
  if ! scratch_make "$tree" $targets; then
    cp "$tree/build/make.log" "$work/logs/$id.build"
    echo "mutants: $id does not build (${work#$top/}/logs/$id.build)"; errors=$((errors + 1)); status=BUILD
  else
    for c in $checks; do
      [ "$(fingerprint "$c")" = "${base[$c]}" ] && continue
      ran+=("$c")
      run_check "$c" "$work/logs/$id-$c.log" || caught+=("$c")
    done
  fi
  scratch_restore "$top" "$tree" $files
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$id" "$step" "$kind" "${caught[*]}" "${ran[*]}" \
    "$status" "$what" >>"$results"
  awk -v id="$id" -v c="${caught[*]:-none}" -v r="${ran[*]:-none}" -v a="$t0" -v b="$(now)" \
    'BEGIN { printf "%-34s caught by: %-28s (ran: %s; %.0f s)\n", id, c, r, b - a }'
done
# Leave the scratch tree built as the solution (the next run starts from it).
scratch_make "$tree" $targets || true
t_end=$(now)

out=$work/mutants.md
[ -z "$pattern" ] && out=$top/docs/mutants.md
seconds=$(awk -v a="$t_start" -v b="$t_end" 'BEGIN { printf "%.0f", b - a }')
tools/check/mutants-report.sh "$results" "$seconds" "${#mutants[@]}" >"$out"
echo
sed -n '/^## Catch rate/,/^## Correct/p' "$out" | sed '$d'
echo "mutants: wrote ${out#$top/} ($seconds s: the solution $(awk -v a="$t_start" -v b="$t_base" 'BEGIN { printf "%.0f", b - a }') s)"
# An alternative-unrefined (a correct form the docs say make stress rejects,
# e.g. the lecture's camera) may fail the stress tests, nothing else.
wrong=$(awk -F'\t' '($3 == "alternative" && $4 != "") ||
                    ($3 == "alternative-unrefined" && $4 != "" && $4 != "stress")' "$results" | wc -l)
[ "$wrong" -eq 0 ] || echo "mutants: $wrong correct alternative(s) fail a test (see ${out#$top/})"
[ $errors -eq 0 ] && [ "$wrong" -eq 0 ]
