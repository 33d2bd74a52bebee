#!/usr/bin/env bash
# Run Criterion test binaries one after the other, one test at a time (--jobs
# 1, so each message sits under its own test), and end with a verdict: one
# line per check, then one synthesis line over all of them. docs/testing.md.
#
# Usage: tests/run.sh [--verbose] BIN...
#   --verbose  every test's [RUN ]/[PASS] line and every check's verdict line
#              (make test-step N); without it, failures only, and per binary
#              either one PASS line or its failing checks' lines (make test).
# Exit status: 0 when every test of every binary passed, 1 otherwise.
# VALGRIND, when set, is the command each binary runs under (make valgrind).
# RT_CACHE=0: run every test, reusing no earlier result (see "Reuse" below).
#
# A check is a Criterion suite: the unit tests of one module (`sphere`), the
# image test (suite `reference_image`), or a saving a doc asks for (suite
# `saving`: a correct solution that does more work than asked, e.g. a shadow
# ray for a light behind the surface, gets WARN, which does not fail the run).
# Its verdict line reads
#   PASS  sphere           8 tests
#   FAIL  sphere           2 of 8 tests failed: sphere_hit_t (read docs/02-intersection.md, "What you write")
#   WARN  saving           1 of 1 tests failed: ... (a saving the doc asks for; the result is right without it)
# The functions and docs come from the failing checks' messages (tests/check.h
# starts each with "function: " and ends it with "read DOC, \"Section\"").
#
# Not written yet. A step whose code (common/ and its own folder) still holds
# a TODO(step NN) of its own is not run: its line reads
#   TODO  06-ambient  not written yet: common/shade.c:25 still holds TODO(step 06)
# (the first such TODO), the stress tests of that step are left out, and so
# are the tracer's tests of that step's program (RT_UNWRITTEN). Such a step
# counts as failing in the exit status: the course is not done.
#
# Reuse. A test program's result is reused, without running it, while
# nothing it depends on changed since it last passed (a failing or crashed
# run is never reused: its messages are shown again). The key, a SHA-1, is
#   the stress tests, step by step (RT_STRESS_ONLY=K runs step K's): every
#     source the stress program and the programs it runs are built from
#     (common/, fast/, steps/, tests/ *.c and *.h, tools/figures/mistakes.c), scenes/,
#     the Makefile and mk/*.mk, the build's flags and configuration
#     ($BUILD/.flags, $BUILD/config.mk), with the text of every solution
#     region of a step after K left out: an edit to step 08's code keeps
#     steps 01 to 07's results;
#   any other test program: its own bytes, every program in $BUILD/bin/,
#     and every file of images/, scenes/ and tests/.
# Results are kept in $BUILD/cache/ (one per program, or per stress step).
#
# Results file. For build/tests/NAME the results are also written to
# build/results/NAME.json (RESULTS_DIR overrides the folder), read from
# Criterion's TAP report (Criterion 2.4.1's JSON report does not escape quotes
# in messages, so it is not used). Its fields:
#   name             the binary's name: a step (02-intersection) or "stress"
#   binary           the path that was run
#   exit_status      the binary's exit status (0 only when all passed)
#   pass             true when no test failed except savings (the exit
#                    status is then 0 or only savings failed)
#   tested, passing, failing, crashing   as in Criterion's synthesis line
#                    (failing counts the crashed tests too), savings excepted
#   savings_missed   failed tests of the `saving` suite
#   checks           one object per suite, in the order of the verdict lines:
#     check          the suite's name ("sphere", "reference_image")
#     kind           "unit", "image" (the image test) or "saving"
#     pass           true when every test of the suite passed
#     tests, failed, crashed   counts (failed includes crashed)
#     functions      the functions under test named by the failing messages
#     docs           the doc pages those messages point to
#     verdict        the verdict line's text after PASS/FAIL and the name
#     failures       one object per failing test: test (its name), status
#                    ("failed", "crashed" or "timed out"), messages (each
#                    check's message, lines joined by "\n", in test order)
set -uo pipefail

verbose=0
if [ "${1:-}" = --verbose ]; then verbose=1; shift; fi

tested=0; passing=0; failing=0; crashing=0; savings=0; status=0; unwritten=; todo_steps=

top=$(cd "$(dirname "$0")/.." && pwd)
# tests/results.awk: TAP report -> verdict lines (stdout) and the results
# JSON (file); the grader (tools/grading/tests.sh) reads reports with it too.
results_awk=$top/tests/results.awk
# The known mistakes' signatures (tools/check/diagnoses.sh; docs/mutants.md,
# "Diagnosis"): a failing check whose signature is there names the mistake.
diagnoses=$top/tests/diagnoses.tsv
[ -f "$diagnoses" ] || diagnoses=
cache=${RT_CACHE:-1}
[ -n "${VALGRIND:-}" ] && cache=0

# todo_of NN: "FILE:LINE" of the first TODO(step NN) in the code step NN is
# built from (common/ and steps/NN-*/), or nothing when the step is written.
todo_of() {
  (cd "$top" && grep -rnE --include='*.[ch]' "TODO\(step $1\)" common steps/"$1"-* 2>/dev/null |
     sort -t: -k1,1 -k2,2n | head -n 1 | cut -d: -f1,2)
}
# Steps 01 .. 08 not written yet, "06 07 08"; the tracer's tests leave their
# programs out (tests/test_trace.c).
for k in 01 02 03 04 05 06 07 08; do
  [ -n "$(todo_of "$k")" ] && unwritten="$unwritten $k"
done
export RT_UNWRITTEN=${unwritten# }

# The key of the stress tests of step K (see "Reuse"): sources with the
# regions of later steps cut, one line each prefixed by its region's step.
src_keyed=
stress_key() {
  local build=$1 k=$2
  if [ -z "$src_keyed" ]; then
    src_keyed=$(mktemp)
    (cd "$top" && {
      find common fast steps tests -name '*.[ch]' -type f; ls tools/figures/mistakes.c Makefile mk/*.mk scenes/* 2>/dev/null
    } | LC_ALL=C sort | while IFS= read -r f; do printf '0 == %s\n' "$f"; awk '
        /\/\* BEGIN (SOLUTION )?step [0-9]+/ { match($0, /step [0-9]+/); step = substr($0, RSTART + 5, RLENGTH - 5) + 0 }
        { print step + 0, $0 }
        /\/\* END (SOLUTION|step [0-9]+) \*\// { step = 0 }' "$f"; done
      cat "$build/.flags" "$build/config.mk" 2>/dev/null | sed 's/^/0 /') >"$src_keyed"
  fi
  awk -v k="$k" '$1 <= k' "$src_keyed" | sha1sum | cut -c1-40
}
# The key of any other test program.
data_sum=
bin_key() {
  local build=$1 bin=$2
  if [ -z "$data_sum" ]; then
    data_sum=$( (cd "$top" && find images scenes tests -type f | LC_ALL=C sort | xargs sha1sum;
                 find "$build/bin" -maxdepth 1 -type f 2>/dev/null | LC_ALL=C sort | xargs -r sha1sum) | sha1sum)
  fi
  printf '%s %s\n' "$(sha1sum < "$bin")" "$data_sum" | sha1sum | cut -c1-40
}

# run_tap BIN TAP [ENV...]: run one test program (its output shown, skipped
# tests left out), its TAP report in TAP; prints nothing else; returns its
# exit status.
run_tap() {
  local bin=$1 tap=$2; shift 2
  local args=(--jobs 1 "--tap=$tap")
  [ "$verbose" = 1 ] && args+=(--verbose)
  # Criterion's own synthesis line comes last, over all binaries; the line
  # about the TAP report is noise to a student.
  # A skipped test (a stress test of a later step, tests/stress.h) is left
  # out of the output (its [RUN ] and [SKIP] lines) and of the counts.
  env "$@" ${VALGRIND:-} "$bin" "${args[@]}" 2>&1 |
    grep --line-buffered -v -e 'Synthesis: Tested:' -e 'Writing tap report' |
    awk '/^\[RUN \]/ { if (run != "") print run; run = $0; fflush(); next }
         /^\[SKIP\]/ { run = ""; next }
         { if (run != "") print run; run = ""; print; fflush() }
         END { if (run != "") print run }'
  local rc=${PIPESTATUS[0]}
  sed -i '/^ok - .* # SKIP /d' "$tap"
  return "$rc"
}
# reusable TAP RC: a complete report of a run that passed.
reusable() { [ "$2" = 0 ] && grep -q '^1\.\.' "$1" && ! grep -q '^not ok' "$1"; }

for bin in "$@"; do
  name=${bin##*/}
  build=$(dirname "$(dirname "$bin")")
  results=${RESULTS_DIR:-$build/results}
  mkdir -p "$results" "$build/cache"
  step=${name%%-*}
  # A step not written yet: its line, no run.
  if [[ $name =~ ^[0-9][0-9]- ]] && [ -z "${RT_STRESS_ONLY:-}" ] && todo=$(todo_of "$step") && [ -n "$todo" ]; then
    echo "==> $name"
    printf 'TODO  %-16snot written yet: %s still holds TODO(step %s)\n' "$name" "$todo" "$step"
    printf '{\n  "name": "%s",\n  "binary": "%s",\n  "exit_status": 1,\n  "pass": false,\n  "not_written": "%s",\n  "tested": 0, "passing": 0, "failing": 0, "crashing": 0,\n  "checks": []\n}\n' \
      "$name" "$bin" "$todo" > "$results/$name.json"
    status=1; todo_steps="$todo_steps $step"; continue
  fi
  tap=$(mktemp); counts=$(mktemp)
  reused=
  if [ "$name" = stress ] && [ -z "${RT_STRESS_ONLY:-}" ]; then
    # The stress tests step by step: each step's result reused while its key
    # holds. Steps not written yet are left out.
    echo "==> $name"
    upto=$((10#${RT_STRESS_STEPS:-08}))
    rc=0; parts=()
    for ((k = 1; k <= upto; k++)); do
      kk=$(printf %02d "$k")
      [[ " $RT_UNWRITTEN " == *" $kk "* ]] && continue
      part=$(mktemp); parts+=("$part")
      key=; [ "$cache" = 1 ] && key=$(stress_key "$build" "$k")
      kept=$build/cache/stress-$kk-$key.tap
      if [ -n "$key" ] && [ -f "$kept" ]; then
        cp "$kept" "$part"; reused="$reused $kk"; continue
      fi
      run_tap "$bin" "$part" RT_STRESS_ONLY="$kk"; r=$?
      [ "$r" = 0 ] || rc=$r
      if [ -n "$key" ] && reusable "$part" "$r"; then
        rm -f "$build/cache/stress-$kk-"*.tap; cp "$part" "$kept"
      fi
    done
    # One report of them all, as one run would write it.
    { echo "TAP version 13"
      echo "1..$(cat "${parts[@]}" /dev/null | grep -cE '^(not )?ok - ')"
      for part in "${parts[@]}"; do grep -v -e '^TAP version' -e '^1\.\.' "$part"; done
    } >"$tap"
    rm -f "${parts[@]}"
  else
    key=; [ "$cache" = 1 ] && key=$(bin_key "$build" "$bin")
    kept=$build/cache/$name-$key.tap
    echo "==> $name"
    if [ -n "$key" ] && [ -f "$kept" ]; then
      cp "$kept" "$tap"; rc=0; reused=" all"
    else
      run_tap "$bin" "$tap"; rc=$?
      if [ -n "$key" ] && reusable "$tap" "$rc"; then
        rm -f "$build/cache/$name-"*.tap; cp "$tap" "$kept"
      fi
    fi
  fi
  if [ -n "$reused" ]; then
    what="its tests"
    if [ "$name" = stress ]; then
      what="the stress tests of step"
      [ "$(wc -w <<<"$reused")" -gt 1 ] && what="${what}s"
      what="$what $(echo $reused | sed 's/ /, /g')"
    fi
    echo "      ($what: the last result reused, nothing they depend on changed since they passed)"
  fi
  [ "$verbose" = 1 ] && echo
  if [ ! -s "$tap" ] || ! grep -q '^1\.\.' "$tap"; then
    echo "FAIL  $name: the test program stopped before reporting (exit $rc); run it alone: $bin --verbose"
    printf '{\n  "name": "%s",\n  "binary": "%s",\n  "exit_status": %d,\n  "pass": false,\n  "tested": 0, "passing": 0, "failing": 0, "crashing": 1,\n  "checks": []\n}\n' \
      "$name" "$bin" "$rc" > "$results/$name.json"
    status=1; crashing=$((crashing + 1)); failing=$((failing + 1)); rm -f "$tap" "$counts"; continue
  fi
  LC_ALL=C awk -v name="$name" -v binary="$bin" -v rc="$rc" -v verbose="$verbose" \
      -v out="$results/$name.json" -v counts="$counts" -v diagnoses="$diagnoses" \
      -v sigout="${RT_SIGNATURES:-}" -f "$results_awk" "$tap"
  read -r t p f c sv bad < "$counts"
  rm -f "$tap" "$counts"
  tested=$((tested + t)); passing=$((passing + p)); failing=$((failing + f)); crashing=$((crashing + c))
  savings=$((savings + sv))
  [ "$f" -eq 0 ] && [ "$bad" -eq 0 ] || status=1
done
[ -n "$src_keyed" ] && rm -f "$src_keyed"
[ $((failing + crashing)) -eq 0 ] || status=1
echo
line="[====] Synthesis: Tested: $tested | Passing: $passing | Failing: $failing | Crashing: $crashing"
[ "$savings" -eq 0 ] || line="$line | Savings missed: $savings"
[ -z "$todo_steps" ] || line="$line | Not written yet: step$([ "$(wc -w <<<"$todo_steps")" -gt 1 ] && echo s) $(echo $todo_steps | sed 's/ /, /g')"
echo "$line"
exit $status
