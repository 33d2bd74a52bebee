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

tested=0; passing=0; failing=0; crashing=0; savings=0; status=0

# tests/results.awk: TAP report -> verdict lines (stdout) and the results
# JSON (file); the grader (tools/grading/tests.sh) reads reports with it too.
results_awk=$(dirname "$0")/results.awk

for bin in "$@"; do
  name=${bin##*/}
  results=${RESULTS_DIR:-$(dirname "$(dirname "$bin")")/results}
  mkdir -p "$results"
  tap=$(mktemp); counts=$(mktemp)
  echo "==> $name"
  args=(--jobs 1 "--tap=$tap")
  [ "$verbose" = 1 ] && args+=(--verbose)
  # Criterion's own synthesis line comes last, over all binaries; the line
  # about the TAP report is noise to a student.
  # A skipped test (a stress test of a later step, tests/stress.h) is left
  # out of the output (its [RUN ] and [SKIP] lines) and of the counts.
  ${VALGRIND:-} "$bin" "${args[@]}" 2>&1 |
    grep --line-buffered -v -e 'Synthesis: Tested:' -e 'Writing tap report' |
    awk '/^\[RUN \]/ { if (run != "") print run; run = $0; fflush(); next }
         /^\[SKIP\]/ { run = ""; next }
         { if (run != "") print run; run = ""; print; fflush() }
         END { if (run != "") print run }'
  rc=${PIPESTATUS[0]}
  sed -i '/^ok - .* # SKIP /d' "$tap"
  [ "$verbose" = 1 ] && echo
  if [ ! -s "$tap" ] || ! grep -q '^1\.\.' "$tap"; then
    echo "FAIL  $name: the test program stopped before reporting (exit $rc); run it alone: $bin --verbose"
    printf '{\n  "name": "%s",\n  "binary": "%s",\n  "exit_status": %d,\n  "pass": false,\n  "tested": 0, "passing": 0, "failing": 0, "crashing": 1,\n  "checks": []\n}\n' \
      "$name" "$bin" "$rc" > "$results/$name.json"
    status=1; crashing=$((crashing + 1)); failing=$((failing + 1)); rm -f "$tap" "$counts"; continue
  fi
  awk -v name="$name" -v binary="$bin" -v rc="$rc" -v verbose="$verbose" \
      -v out="$results/$name.json" -v counts="$counts" -f "$results_awk" "$tap"
  read -r t p f c sv bad < "$counts"
  rm -f "$tap" "$counts"
  tested=$((tested + t)); passing=$((passing + p)); failing=$((failing + f)); crashing=$((crashing + c))
  savings=$((savings + sv))
  [ "$f" -eq 0 ] && [ "$bad" -eq 0 ] || status=1
done
[ $((failing + crashing)) -eq 0 ] || status=1
echo
line="[====] Synthesis: Tested: $tested | Passing: $passing | Failing: $failing | Crashing: $crashing"
[ "$savings" -eq 0 ] || line="$line | Savings missed: $savings"
echo "$line"
exit $status
