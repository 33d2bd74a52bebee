# The solution regions of a C source file, for tools/check/starter.sh,
# tools/check/regions.sh, tools/check/check-regions.sh and tools/check/check-starter.sh
# (docs/instructors.md, "The starter tree"). A region is
#   /* BEGIN SOLUTION step NN */ ...the solution... [/* HINT: ... */]
#   [/* STUB: code */] /* END SOLUTION */
#
# Variables (awk -v):
#   mode=stub (default)  copy the file, replacing each region of a step >=
#                        keep_below by the student's region
#                          <indent>/* BEGIN step NN: NAME */
#                          <indent>/* TODO(step NN): <what> (docs/NN-name.md, "What you write") */
#                          <indent><the STUB line's code, if any>
#                          <indent>/* END step NN */
#                        and a region of a step below keep_below by the same
#                        markers around its solution (HINT and STUB lines
#                        dropped). <what> is the region's HINT, which must
#                        name NAME's function, else "complete FUNCTION" (a
#                        region inside a function) or "write F1 and F2, or
#                        helpers of your own" (a region at file scope).
#     keep_below=K       (default 1: every region stubbed)
#     names="01=01-film 02=..."  step number -> folder, for the docs page
#     only=I[,J...]      stub the I-th (J-th...) region of the file alone
#                        (1-based) and copy every other region as it is,
#                        markers included
#   mode=list            print one line per region instead:
#                        FILE <tab> FIRST <tab> LAST <tab> STEP <tab> NAME
#                        NAME: the function the region sits in; for a region
#                        at file scope, the functions it defines (a,b); else
#                        its HINT; else "-".
# Malformed regions (a BEGIN inside a region, an END without a BEGIN, a region
# that never ends) print "starter: FILE:LINE: ..." on stderr and exit 1.

function fail(msg) { printf "starter: %s:%d: %s\n", FILENAME, FNR, msg > "/dev/stderr"; bad = 1; exit 1 }
function defined_name(line,    f) { f = line; sub(/\(.*/, "", f); sub(/.*[ \t*]/, "", f); return f }
function stubbed() { return only != "" ? ((count "") in chosen) : !keep }
# "a,b,c" -> "a, b and c"
function spoken(list,    parts, n, k, s) {
  n = split(list, parts, ",")
  s = parts[1]
  for (k = 2; k <= n; k++) s = s (k == n ? " and " : ", ") parts[k]
  return s
}
# The TODO line's text: the HINT or a default, then the step doc's section.
function todo_text(name,    what, fns, n, k, named) {
  if (hint == "") {
    what = indent == "" ? "write " spoken(name) ", or helpers of your own" : "complete " name
  } else {
    # The HINT must name the function (or one of those the region defines).
    n = split(name, fns, ",")
    for (k = 1; k <= n; k++) if (index(hint, fns[k])) named = 1
    if (!named) { FNR = start; fail("the HINT line must name " spoken(name) ": " hint) }
    what = hint
  }
  if (step in doc) what = what " (docs/" doc[step] ".md, \"What you write\")"
  return "TODO(step " step "): " what
}
BEGIN {
  n = split(names, pairs, " ")
  for (k = 1; k <= n; k++) { split(pairs[k], kv, "="); doc[kv[1]] = kv[2] }
  if (mode == "") mode = "stub"
  if (keep_below == "") keep_below = 1
  n = split(only, picked, ","); for (k = 1; k <= n; k++) chosen[picked[k] + 0] = 1
}
FNR == 1 { func_name = ""; count = 0; in_region = 0 }
# A function definition starts at column 0; remember it (outside a region: the
# enclosing function; inside one at file scope: a function the region defines).
/^[A-Za-z_][A-Za-z_0-9 \t*]*[ \t*]\**[A-Za-z_][A-Za-z_0-9]*\(/ && !/;[ \t]*$/ {
  if (!in_region) func_name = defined_name($0)
  else if (indent == "") defines = defines (defines == "" ? "" : ",") defined_name($0)
}
/\/\* BEGIN SOLUTION step [0-9][0-9] \*\// {
  if (in_region) fail("BEGIN SOLUTION inside another region (line " start ")")
  in_region = 1; start = FNR; stub = ""; hint = ""; defines = ""; body = ""; count++
  step = $0; sub(/.*BEGIN SOLUTION step /, "", step); step = substr(step, 1, 2)
  indent = $0; sub(/[^ \t].*/, "", indent)
  keep = (step + 0 < keep_below)
  raw = $0 "\n"
  next
}
/BEGIN SOLUTION/ { fail("expected '/* BEGIN SOLUTION step NN */', found: " $0) }
in_region && /\/\* END SOLUTION \*\// {
  in_region = 0
  name = indent == "" ? defines : func_name
  if (mode == "list") {
    if (name == "") name = hint != "" ? hint : "-"
    printf "%s\t%d\t%d\t%s\t%s\n", FILENAME, start, FNR, step, name
    next
  }
  if (only != "" && !stubbed()) { printf "%s%s\n", raw, $0; next }
  if (name == "") name = "-"
  printf "%s/* BEGIN step %s: %s */\n", indent, step, spoken(name)
  if (stubbed()) {
    print indent "/* " todo_text(name) " */"
    if (stub != "") print indent stub
  } else {
    printf "%s", body
  }
  printf "%s/* END step %s */\n", indent, step
  next
}
/END SOLUTION/ { fail("END SOLUTION without a BEGIN") }
in_region { raw = raw $0 "\n" }
in_region && /^[ \t]*\/\* STUB: .*\*\/[ \t]*$/ {
  stub = $0; sub(/^[ \t]*\/\* STUB: /, "", stub); sub(/[ \t]*\*\/[ \t]*$/, "", stub)
  next
}
in_region && /^[ \t]*\/\* HINT: .*\*\/[ \t]*$/ {
  hint = $0; sub(/^[ \t]*\/\* HINT: /, "", hint); sub(/[ \t]*\*\/[ \t]*$/, "", hint)
  next
}
mode == "list" { next }
in_region { body = body $0 "\n"; next }
{ print }
END { if (!bad && in_region) { FNR = start; fail("region never ends (no END SOLUTION)") } }
