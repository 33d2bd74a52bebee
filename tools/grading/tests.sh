# Sourced by tools/grading/base.sh and one.sh: a step's tests, run as
# Criterion runs them, read from Criterion's TAP report with tests/results.awk
# (the verdicts make test-step prints; docs/grading.md, "Checks"). Uses res,
# GRADE_BASE, GRADE_SLOWER, check() and slug().

# tap_times FILE: each test of a TAP report: SUITE TEST STATUS SECONDS
# (tab-separated; STATUS ok or not ok).
tap_times() {
  sed -n 's/^\(\(not \)\{0,1\}ok\) - \([^: ]*\)::\([^ ]*\) .*(\([0-9.]*\)s).*/\3\t\4\t\1\t\5/p' "$1"
}

# The test's own time limit: GRADE_SLOWER (10) times the solution's time, at
# least GRADE_TEST_MIN (5) seconds; in a starter's base, whose times are the
# stubs', GRADE_UNSOLVED_TEST_MIN (60).
test_timeouts() {
  local m=${GRADE_TEST_MIN:-5}
  [ "$(cat "$GRADE_BASE/solution.txt" 2>/dev/null)" != none ] || m=${GRADE_UNSOLVED_TEST_MIN:-60}
  awk -F'\t' -v s="$1" -v k="${GRADE_SLOWER:-10}" -v m="$m" \
    '$1 == s { t = k * $5; printf "%s::%s %d\n", $2, $3, t < m ? m : t + 1 }' "$GRADE_BASE/tests.tsv"
}

# watch_tests PID LOG TIMEOUTS: while the test program PID runs, follow its
# progress lines ([RUN ] suite::test, then [PASS] or [FAIL]) in LOG; when one
# test runs past its limit (TIMEOUTS: "suite::test seconds" lines), stop the
# program and print that test. Its output can only make its own tests fail:
# a line it fakes names a test to stop, never one to pass.
watch_tests() {
  local pid=$1 log=$2 cur="" since now line limit
  declare -A limits
  while read -r line limit; do limits[$line]=$limit; done <<<"$3"
  while kill -0 "$pid" 2>/dev/null; do
    sleep 0.2
    line=$(tail -c 4096 "$log" 2>/dev/null | grep -a -E '^\[(RUN |PASS|FAIL|SKIP)\] ' | tail -n 1)
    case $line in
      "[RUN ] "*) line=${line#"[RUN ] "}; line=${line%%[[:space:]]*}
                  now=$(date +%s)
                  if [ "$line" != "$cur" ]; then cur=$line since=$now
                  elif [ $((now - since)) -gt "${limits[$cur]:-${GRADE_TEST_MIN:-5}}" ]; then
                    kill -TERM "$pid" 2>/dev/null; echo "$cur"; return
                  fi ;;
      *) cur="" ;;
    esac
  done
}

# run_tests TREE STEP: the step's test program in the sandbox, one job. Its
# report (TAP) goes to a file of an unpredictable name outside the sandbox,
# passed as descriptor 3, so nothing the submission prints is read as a
# result. A test that runs past its limit is stopped, counted as timed out,
# and the program runs again without it (Criterion 2.4 has no per-test limit
# for tests that set none).
run_tests() {
  local tree=$1 step=$2 report wall st k=1 hung stopped="" filter=() log timeouts
  wall=$(awk -F'\t' -v s="$step" '$1 == s { print $3 }' "$GRADE_BASE/limits.tsv")
  wall=${GRADE_TEST_WALL:-$wall}
  timeouts=$(test_timeouts "$step")
  mkdir -p "$res/logs"
  while :; do
    report=$(mktemp "$res/.report.XXXXXXXXXX")
    # The sandboxed user reopens it through /dev/fd/3 (Criterion opens the
    # path): it may write the file, but cannot see the folder it is in.
    sandbox_own "$report"
    log=$res/logs/$step.log; [ $k = 1 ] || log=$res/logs/$step.$k.log
    sandbox_start "$wall" "$wall" "$log" "$tree" -- "build/tests/$step" --jobs 1 --verbose \
      --color=never --tap=/dev/fd/3 "${filter[@]}" 3>"$report"
    hung=$(watch_tests "$SANDBOX_PID" "$log" "$timeouts")
    wait "$SANDBOX_PID"; st=$?
    [ -n "$hung" ] || break
    stopped="$stopped${stopped:+|}${hung/::/\/}"
    filter=(--filter "!($stopped)")
    rm -f "$report"
    k=$((k + 1))
  done
  if ! grep -q '^1\.\.[0-9]' "$report"; then
    fail_step_tests "$step" "the test program stopped before writing its report: $(sandbox_status_text \
      $st "$wall" "$wall") (logs/${log##*/})"
  else
    # A test stopped at its limit was skipped in the last run: report it as
    # timed out, as Criterion reports a test past its own .timeout.
    local t
    for t in ${stopped//|/ }; do
      sed -i "s|^ok - ${t/\//::} .*# SKIP.*|not ok - ${t/\//::} timed out (stopped at its limit)|" "$report"
    done
    awk -v name="$step" -v binary="build/tests/$step" -v rc="$st" -v verbose=0 -v out="$report.json" \
      -v counts=/dev/null -f "$GRADE_BASE/solved/tests/results.awk" "$report" >/dev/null
    results_to_checks "$step" "$report.json"
  fi
  rm -f "$report" "$report.json"
}

# The unit-test checks of STEP (not its hidden scenes) all fail with WHY.
fail_step_tests() {
  local c
  for c in $(step_suites "$1"); do check "$c" FAIL "$2"; done
}

# results_to_checks STEP JSON: a check per suite of the solution's run, from
# the results file (tests/results.awk): it passes when all its tests ran and
# passed; its reason is the verdict line make test-step prints; the failing
# tests' messages go to details/CHECK.txt (30 lines a test at most).
results_to_checks() {
  local step=$1 json=$2 suite want got pass why
  for suite in $(step_suites "$step" | sed 's|.*/||'); do
    want=$(awk -F'\t' -v s="$step" -v u="$suite" '$1 == s && $2 == u' "$GRADE_BASE/tests.tsv" | grep -c .)
    IFS=$'\t' read -r got pass why < <(jq -r --arg u "$suite" \
      '[.checks[] | select(.check == $u)][0] // {tests: 0, pass: false, verdict: "did not run"} |
       [.tests, .pass, .verdict] | @tsv' "$json" 2>/dev/null ||
      printf '0\tfalse\tthe test report could not be read\n')
    if [ "$got" -lt "$want" ]; then
      why="$why; $((want - got)) of the solution's $want tests did not run"; pass=false
    fi
    if [ "$pass" = true ]; then check "$step/$suite" PASS "$why"; else check "$step/$suite" FAIL "$why"; fi
    jq -r --arg u "$suite" '.checks[] | select(.check == $u) | .failures[] |
        "\(.test): \(.status)", (.messages | join("\n") | split("\n") | .[0:30][] | "    " + .),
        (if (.messages | join("\n") | split("\n") | length) > 30 then "    ..." else empty end)' "$json" \
      >"$res/details/$(slug "$step/$suite").txt"
    [ -s "$res/details/$(slug "$step/$suite").txt" ] || rm -f "$res/details/$(slug "$step/$suite").txt"
  done
}
