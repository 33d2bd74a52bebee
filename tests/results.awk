# Criterion's TAP report of one test program -> one verdict line per check
# (stdout) and the results file (JSON, the fields tests/run.sh lists).
# Variables: name, binary, rc (its exit status), verbose (0/1), out (the
# JSON's path), counts (a file for "tested passing failing crashing savings
# bad"), diagnoses (tests/diagnoses.tsv, or "" for none), sigout (a file that
# gets "NAME CHECK SIGNATURE" for each failing check, or "": tools/check/diagnoses.sh). Run by tests/run.sh and by the grader (tools/grading/tests.sh).
function esc(s,    i, c, p) {
  gsub(/\\/, "\\\\\\\\", s); gsub(/"/, "\\\"", s); gsub(/\t/, "\\t", s); gsub(/\r/, "", s)
  gsub(/\n/, "\\n", s)
  # Other control bytes (a test may quote one) as \u00XX: JSON allows none raw.
  for (i = 1; i < 32; i++) {
    c = sprintf("%c", i)
    while ((p = index(s, c)) > 0) s = substr(s, 1, p - 1) sprintf("\\u%04x", i) substr(s, p + 1)
  }
  return s
}
function q(s) { return "\"" esc(s) "\"" }
# The signature of a failing check: its failing tests, their status and their
# messages, with each number rounded to 3 significant digits and the "read
# DOC" and "this test also runs" lines left out (they name, they do not
# measure), hashed to 16 hex digits. The same mistake gives the same
# signature on another compiler or machine; tools/check/diagnoses.sh records each
# mutant's, and the verdict line names the mutant whose signature it meets.
function norm(t,    out, line, n, i, lines, num) {
  out = ""
  n = split(t, lines, "\n")
  for (i = 1; i <= n; i++) {
    line = lines[i]
    if (line ~ /^ *read / || line ~ /^ *this test also runs /) continue
    num = ""
    while (match(line, /-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?/)) {
      num = num substr(line, 1, RSTART - 1) sprintf("%.3g", substr(line, RSTART, RLENGTH) + 0)
      line = substr(line, RSTART + RLENGTH)
    }
    out = out num line "\n"
  }
  return out
}
function hash(t,    i, c, h1, h2) {
  if (!ord_ready) { for (i = 1; i < 256; i++) ord[sprintf("%c", i)] = i; ord_ready = 1 }
  h1 = 7; h2 = 11
  for (i = 1; i <= length(t); i++) {
    c = ord[substr(t, i, 1)] + 0
    h1 = (h1 * 131 + c) % 2147483647; h2 = (h2 * 137 + c + 1) % 2147483629
  }
  return sprintf("%08x%08x", h1, h2)
}
# The diagnoses table (tests/diagnoses.tsv, written by tools/check/diagnoses.sh):
# CHECK SIGNATURE MUTANT STEP WHAT, one a line; '#' lines are comments.
function load_diagnoses(    line, f) {
  if (diagnoses == "") return
  while ((getline line < diagnoses) > 0) {
    if (line ~ /^#/ || line == "") continue
    split(line, f, "\t")
    if ((f[1] SUBSEP f[2]) in diag_what) {
      if (index(diag_what[f[1], f[2]], f[5]) == 0) diag_what[f[1], f[2]] = diag_what[f[1], f[2]] ", or " f[5]
    } else diag_what[f[1], f[2]] = f[5]
  }
  close(diagnoses)
}
BEGIN { load_diagnoses() }
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
    nf = 0; nd = 0; split("", seen_f); split("", seen_d); fn_list = ""; fails_json = ""; sig_text = ""
    for (k = n_fail; k >= 1; k--) {   # TAP lists a suite's tests in reverse run order
      if (fail_suite[k] != s) continue
      msgs_json = ""; sig_msgs = ""
      for (m = n_msg[k]; m >= 1; m--) {   # and a test's messages in reverse too
        t = message[k, m]
        sig_msgs = sig_msgs norm(t)
        msgs_json = msgs_json (msgs_json == "" ? "" : ", ") q(t)
        f = t; sub(/\n.*/, "", f)
        if (f ~ /^[A-Za-z_][A-Za-z_0-9]*(, [A-Za-z_][A-Za-z_0-9]*)*( \([^)]*\))?: /) {
          sub(/: .*/, "", f)
          st = ""
          if (match(f, /\(step [0-9][0-9]/)) st = substr(f, RSTART + 6, 2)
          sub(/ \(.*/, "", f)
          cnt = split(f, parts, ", ")
          d = ""
          if (match(t, /read docs\/[A-Za-z0-9_.-]+\.md(, "[^"\n]*")?/)) {
            d = substr(t, RSTART + 5, RLENGTH - 5)
            dfile = d; sub(/,.*/, "", dfile)
            if (dfile ~ /^docs\/[0-9][0-9]-/) d = dfile ", \"What you write\""
          }
          if (st == "" && match(d, /^docs\/[0-9][0-9]-/)) st = substr(d, 6, 2)
          for (p = 1; p <= cnt; p++) if (!(parts[p] in seen_f)) { seen_f[parts[p]] = 1; fn[++nf] = parts[p]; fn_doc[nf] = d; fn_step[nf] = st }
          if (d != "" && !(d in seen_d)) { seen_d[d] = 1; doc[++nd] = d }
        }
      }
      fails_json = fails_json (fails_json == "" ? "" : ",") "\n        {\"test\": " q(fail_test[k]) ", \"status\": " q(fail_status[k]) ", \"messages\": [" msgs_json "]}"
      sig_text = sig_text fail_test[k] "|" fail_status[k] "|" sig_msgs "\n"
    }
    sig = ""; diagnosis = ""
    if (failed[s] > 0) {
      # The image test's pictures differ from step to step: its signature
      # names the step's program too.
      sig = hash((s == "reference_image" ? name "\n" : "") sig_text)
      if ((s SUBSEP sig) in diag_what) diagnosis = "looks like " diag_what[s, sig]
      if (sigout != "") print name "\t" s "\t" sig > sigout
    }
    # "f, g (step 04, read D1); h (step 05, read D2)": functions grouped by
    # the doc they point to, with their steps; a diagnosis follows the
    # functions when there is one group ("f (step 04): looks like ... (read
    # D1)"), else ends the line.
    ngrp = 0
    for (di = 1; di <= nd + 1; di++) {
      grp = ""; gst = ""
      for (p = 1; p <= nf; p++) if ((di <= nd && fn_doc[p] == doc[di]) || (di > nd && fn_doc[p] == "")) {
        grp = grp (grp == "" ? "" : ", ") fn[p]
        if (fn_step[p] != "" && index(" " gst, " " fn_step[p]) == 0) gst = gst (gst == "" ? "" : ", ") fn_step[p]
      }
      if (grp == "") continue
      ngrp++; grp_fns[ngrp] = grp; grp_step[ngrp] = gst; grp_doc[ngrp] = di <= nd ? doc[di] : ""
    }
    for (g = 1; g <= ngrp; g++) {
      grp = grp_fns[g]; st = grp_step[g] != "" ? "step " grp_step[g] : ""
      if (diagnosis != "" && ngrp == 1) {
        if (st != "") grp = grp " (" st ")"
        grp = grp ": " diagnosis
        if (grp_doc[g] != "") grp = grp " (read " grp_doc[g] ")"
      } else if (st != "" || grp_doc[g] != "")
        grp = grp " (" st (st != "" && grp_doc[g] != "" ? ", " : "") (grp_doc[g] != "" ? "read " grp_doc[g] : "") ")"
      fn_list = fn_list (fn_list == "" ? "" : "; ") grp
    }
    if (diagnosis != "" && ngrp != 1) fn_list = fn_list (fn_list == "" ? "" : "; ") diagnosis
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
    json = json "],\n      \"signature\": " q(sig) ", \"diagnosis\": " q(diagnosis) ","
    json = json "\n      \"verdict\": " q(verdict) ",\n      \"failures\": [" fails_json (fails_json == "" ? "" : "\n      ") "]}"
  }
  json = json (n_suites ? "\n  " : "") "]\n}\n"
  printf "%s", json > out
  if (!verbose && nfailed == 0)
    printf "PASS  %-" width "s%d checks, %d tests\n", name, n_suites, total
  print total, total - nfailed - nsaving, nfailed, ncrashed, nsaving, ((rc == 0 || nsaving > 0) ? 0 : 1) > counts
}
