# Sourced by tools/grading/base.sh and one.sh: a step's unit tests, run as
# Criterion runs them, read from Criterion's TAP report (docs/grading.md,
# "Checks"). Uses res, GRADE_BASE, GRADE_SLOWER, check() and slug().

# tap_tsv FILE: one line per test of a TAP report: SUITE TEST STATUS SECONDS
# MESSAGE (tab-separated; the message's lines joined by \037). STATUS is
# PASSED, SKIPPED, FAILED, TIMED OUT or CRASHED.
tap_tsv() {
  awk '
    function flush() { if (name != "") printf "%s\t%s\t%s\t%s\t%s\n", suite, test, status, secs, msg; name = "" }
    /^(not )?ok - / {
      flush(); ok = $1 == "ok"
      line = $0; sub(/^(not )?ok - /, "", line)
      name = line; sub(/[ \t].*/, "", name); rest = substr(line, length(name) + 1)
      suite = name; sub(/::.*/, "", suite); test = name; sub(/^[^:]*::/, "", test)
      secs = 0; if (match(rest, /\([0-9.]+s\)/)) secs = substr(rest, RSTART + 1, RLENGTH - 3)
      msg = ""
      if (ok) status = rest ~ /# SKIP/ ? "SKIPPED" : "PASSED"
      else if (rest ~ /^ *timed out/) status = "TIMED OUT"
      else if (rest ~ /unexpected signal/) { status = "CRASHED"; msg = rest; sub(/^ */, "", msg) }
      else status = "FAILED"
      next
    }
    name != "" && /^  - / { l = $0; sub(/^  - /, "", l); sub(/ *\|\+$/, "", l); msg = msg (msg == "" ? "" : "\037") l; next }
    name != "" && /^      / { l = $0; sub(/^      /, "", l); gsub(/\t/, " ", l); msg = msg "\037  " l; next }
    END { flush() }' "$1"
}

# The test's own time limit: GRADE_SLOWER (10) times the solution's time, at
# least GRADE_TEST_MIN (10) seconds.
test_timeouts() {
  awk -F'\t' -v s="$1" -v k="${GRADE_SLOWER:-10}" -v m="${GRADE_TEST_MIN:-10}" \
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
                  elif [ $((now - since)) -gt "${limits[$cur]:-${GRADE_TEST_MIN:-10}}" ]; then
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
    tap_tsv "$report" | awk -F'\t' -v OFS='\t' -v stopped="|$stopped|" \
      '{ n = $1 "/" $2; if (index(stopped, "|" n "|")) { $3 = "TIMED OUT"; $5 = "ran past its limit: stopped" } print }' \
      >"$report.tsv"
    tests_to_checks "$step" "$report.tsv"
  fi
  rm -f "$report" "$report.tsv"
}

# The unit-test checks of STEP (not its hidden scenes) all fail with WHY.
fail_step_tests() {
  local c
  for c in $(GRADE_PLAN=/dev/null step_checks "$1"); do check "$c" FAIL "$2"; done
}

# tests_to_checks STEP GOT: each expected test (the solution's list) looked up
# in the report; a check passes when all its tests passed. A test missing from
# the report failed ("did not run"). Failing tests' messages go to
# details/CHECK.txt (30 lines a test at most).
tests_to_checks() {
  awk -F'\t' -v s="$1" -v it="$IMAGE_TEST" -v details="$res/details" '
    function key(suite, test) { return s "/" (suite == "image" && test == it ? "image-test" : suite) }
    FILENAME == ARGV[1] { st[$1 "\t" $2] = $3; msg[$1 "\t" $2] = $5; next }
    $1 != s { next }
    {
      c = key($2, $3); if (!(c in n)) order[++k] = c
      n[c]++
      status = ($2 "\t" $3) in st ? st[$2 "\t" $3] : "DID NOT RUN"
      if (status == "PASSED") next
      bad[c]++; if (bad[c] <= 3) names[c] = names[c] (bad[c] > 1 ? ", " : "") $3
      f = c; gsub("/", "_", f); f = details "/" f ".txt"
      m = msg[$2 "\t" $3]; nl = split(m, ml, "\037"); m = ""
      for (i = 1; i <= nl && i <= 30; i++) m = m (i > 1 ? "\n    " : "") ml[i]
      if (nl > 30) m = m "\n    ... (" nl - 30 " more lines)"
      printf "%s: %s\n    %s\n", $3, status, (m == "" ? "(no message)" : m) >> f
      close(f)
    }
    END {
      for (i = 1; i <= k; i++) {
        c = order[i]
        if (!bad[c]) printf "%s\tPASS\tall %d tests pass\n", c, n[c]
        else printf "%s\tFAIL\t%d of %d tests fail: %s%s\n", c, bad[c], n[c], names[c], (bad[c] > 3 ? ", ..." : "")
      }
    }' "$2" "$GRADE_BASE/tests.tsv" >>"$res/checks.tsv"
}
