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

# awk: TAP report -> verdict lines (stdout) and the results JSON (file).
read -r -d '' TAP_AWK <<'AWK' || true
function esc(s) {
  gsub(/\\/, "\\\\\\\\", s); gsub(/"/, "\\\"", s); gsub(/\t/, "\\t", s); gsub(/\r/, "", s)
  gsub(/\n/, "\\n", s)
  return s
}
function q(s) { return "\"" esc(s) "\"" }
function suite_of(id) { s = id; sub(/::.*/, "", s); return s }
function add_suite(s) { if (!(s in tests)) { order[++n_suites] = s; tests[s] = 0; failed[s] = 0; crashed[s] = 0 } }
function end_message() {
  if (msg != "") { n_msg[cur]++; message[cur, n_msg[cur]] = msg }
  msg = ""
}
# One test result line: "ok - suite::name  (0.00s)" or "not ok - suite::name reason".
/^(not )?ok - / {
  end_message(); in_fail = 0
  ok = ($0 ~ /^ok/)
  line = $0; sub(/^(not )?ok - /, "", line)
  id = line; sub(/ .*/, "", id)
  s = suite_of(id); add_suite(s); tests[s]++
  if (ok) next
  failed[s]++
  cur = ++n_fail; fail_suite[cur] = s; fail_test[cur] = substr(id, length(s) + 3); n_msg[cur] = 0
  fail_status[cur] = "failed"
  if (line ~ / timed out/) { fail_status[cur] = "timed out"; crashed[s]++ }
  else if (line ~ / unexpected signal/) {
    fail_status[cur] = "crashed"; crashed[s]++
    where = line; sub(/.*unexpected signal after /, "", where); fail_where[cur] = where
  }
  in_fail = 1
  next
}
in_fail && /^  - .*: \|\+$/ { end_message(); started = 1; next }
in_fail && /^      / {
  text = substr($0, 7)
  if (msg == "") { sub(/^Assertion failed: /, "", text); msg = text } else msg = msg "\n" text
  next
}
in_fail && /^  \.\.\./ { end_message(); in_fail = 0; next }
END {
  end_message()
  # Checks in a fixed order: the unit suites by name, the image test last.
  for (i = 1; i <= n_suites; i++)
    for (j = i + 1; j <= n_suites; j++) {
      a = order[i]; b = order[j]
      ka = (a == "reference_image") "" a; kb = (b == "reference_image") "" b
      if (kb < ka) { order[i] = b; order[j] = a }
    }
  width = 16
  for (i = 1; i <= n_suites; i++) if (length(order[i]) + 2 > width) width = length(order[i]) + 2
  total = 0; nfailed = 0; ncrashed = 0; nsaving = 0
  for (i = 1; i <= n_suites; i++) {
    s = order[i]; total += tests[s]; ncrashed += crashed[s]
    if (s == "saving") nsaving += failed[s]; else nfailed += failed[s]
  }
  json = "{\n  \"name\": " q(name) ",\n  \"binary\": " q(binary) ",\n  \"exit_status\": " rc ","
  json = json "\n  \"pass\": " ((nfailed == 0 && ncrashed == 0 && (rc == 0 || nsaving > 0)) ? "true" : "false") ","
  json = json "\n  \"tested\": " total ", \"passing\": " (total - nfailed - nsaving) ", \"failing\": " nfailed ", \"crashing\": " ncrashed ","
  json = json "\n  \"savings_missed\": " nsaving ","
  json = json "\n  \"checks\": ["
  for (i = 1; i <= n_suites; i++) {
    s = order[i]
    # Functions and docs named by this suite's failing messages, first seen first.
    nf = 0; nd = 0; split("", seen_f); split("", seen_d); fn_list = ""; fails_json = ""
    for (k = n_fail; k >= 1; k--) {   # TAP lists a suite's tests in reverse run order
      if (fail_suite[k] != s) continue
      msgs_json = ""
      for (m = n_msg[k]; m >= 1; m--) {   # and a test's messages in reverse too
        t = message[k, m]
        msgs_json = msgs_json (msgs_json == "" ? "" : ", ") q(t)
        f = t; sub(/\n.*/, "", f)
        if (f ~ /^[A-Za-z_][A-Za-z_0-9]*(, [A-Za-z_][A-Za-z_0-9]*)*( \([^)]*\))?: /) {
          sub(/: .*/, "", f); sub(/ \(.*/, "", f)
          cnt = split(f, parts, ", ")
          d = ""
          if (match(t, /read docs\/[A-Za-z0-9_.-]+\.md(, "[^"\n]*")?/)) {
            d = substr(t, RSTART + 5, RLENGTH - 5)
            dfile = d; sub(/,.*/, "", dfile)
            if (dfile ~ /^docs\/[0-9][0-9]-/) d = dfile ", \"What you write\""
          }
          for (p = 1; p <= cnt; p++) if (!(parts[p] in seen_f)) { seen_f[parts[p]] = 1; fn[++nf] = parts[p]; fn_doc[nf] = d }
          if (d != "" && !(d in seen_d)) { seen_d[d] = 1; doc[++nd] = d }
        }
      }
      fails_json = fails_json (fails_json == "" ? "" : ",") "\n        {\"test\": " q(fail_test[k]) ", \"status\": " q(fail_status[k]) ", \"messages\": [" msgs_json "]}"
    }
    # "f, g (read D1); h (read D2)": functions grouped by the doc they point to.
    for (di = 1; di <= nd + 1; di++) {
      grp = ""
      for (p = 1; p <= nf; p++) if ((di <= nd && fn_doc[p] == doc[di]) || (di > nd && fn_doc[p] == "")) grp = grp (grp == "" ? "" : ", ") fn[p]
      if (grp == "") continue
      if (di <= nd) grp = grp " (read " doc[di] ")"
      fn_list = fn_list (fn_list == "" ? "" : "; ") grp
    }
    kind = s == "reference_image" ? "image" : s == "saving" ? "saving" : "unit"
    if (failed[s] == 0) {
      verdict = tests[s] " test" (tests[s] == 1 ? "" : "s")
    } else {
      verdict = failed[s] " of " tests[s] " tests failed"
      if (crashed[s] > 0) verdict = verdict " (" crashed[s] " crashed or timed out)"
      if (fn_list != "") verdict = verdict ": " fn_list
      else if (crashed[s] > 0) verdict = verdict ": the code under test stopped the test (a crash or an endless loop); run it alone: " binary " --verbose --filter '" s "/*'"
      if (kind == "saving") verdict = verdict "; a saving the doc asks for: the result is right without it"
    }
    word = failed[s] == 0 ? "PASS" : kind == "saving" ? "WARN" : "FAIL"
    if (failed[s] > 0 || verbose) printf "%s  %-" width "s%s\n", word, s, verdict
    json = json (i > 1 ? "," : "") "\n    {\"check\": " q(s) ", \"kind\": " q(kind)
    json = json ", \"pass\": " (failed[s] ? "false" : "true") ", \"tests\": " tests[s] ", \"failed\": " failed[s] ", \"crashed\": " crashed[s] ","
    json = json "\n      \"functions\": ["
    for (p = 1; p <= nf; p++) json = json (p > 1 ? ", " : "") q(fn[p])
    json = json "], \"docs\": ["
    for (p = 1; p <= nd; p++) { dd = doc[p]; sub(/,.*/, "", dd); json = json (p > 1 ? ", " : "") q(dd) }
    json = json "],\n      \"verdict\": " q(verdict) ",\n      \"failures\": [" fails_json (fails_json == "" ? "" : "\n      ") "]}"
  }
  json = json (n_suites ? "\n  " : "") "]\n}\n"
  printf "%s", json > out
  if (!verbose && nfailed == 0)
    printf "PASS  %-" width "s%d checks, %d tests\n", name, n_suites, total
  print total, total - nfailed - nsaving, nfailed, ncrashed, nsaving, ((rc == 0 || nsaving > 0) ? 0 : 1) > counts
}
AWK

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
  ${VALGRIND:-} "$bin" "${args[@]}" 2>&1 | grep -v -e 'Synthesis: Tested:' -e 'Writing tap report'
  rc=${PIPESTATUS[0]}
  [ "$verbose" = 1 ] && echo
  if [ ! -s "$tap" ] || ! grep -q '^1\.\.' "$tap"; then
    echo "FAIL  $name: the test program stopped before reporting (exit $rc); run it alone: $bin --verbose"
    printf '{\n  "name": "%s",\n  "binary": "%s",\n  "exit_status": %d,\n  "pass": false,\n  "tested": 0, "passing": 0, "failing": 0, "crashing": 1,\n  "checks": []\n}\n' \
      "$name" "$bin" "$rc" > "$results/$name.json"
    status=1; crashing=$((crashing + 1)); failing=$((failing + 1)); rm -f "$tap" "$counts"; continue
  fi
  awk -v name="$name" -v binary="$bin" -v rc="$rc" -v verbose="$verbose" \
      -v out="$results/$name.json" -v counts="$counts" "$TAP_AWK" "$tap"
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
