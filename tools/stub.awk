# The solution regions of a C source file, for tools/starter.sh,
# tools/regions.sh and tools/check-regions.sh (README.md, "For instructors").
# A region is
#   /* BEGIN SOLUTION step NN */ ...the solution... [/* HINT: ... */]
#   [/* STUB: code */] /* END SOLUTION */
#
# Variables (awk -v):
#   mode=stub (default)  copy the file, replacing each region of a step >=
#                        keep_below by
#                          <indent>/* TODO(step NN): <hint> */
#                          <indent><the STUB line's code, if any>
#                        and dropping only the marker lines of regions of steps
#                        below keep_below. The hint is the region's HINT line
#                        when there is one, else "complete <enclosing function>
#                        (docs/NN-name.md)".
#     keep_below=K       (default 1: every region stubbed)
#     names="01=01-film 02=..."  step number -> folder, for the docs page
#     only=I             stub the I-th region of the file alone (1-based) and
#                        copy every other region as it is, markers included
#   mode=list            print one line per region instead:
#                        FILE <tab> FIRST <tab> LAST <tab> STEP <tab> NAME
#                        NAME: the function the region sits in; for a region
#                        at file scope, the functions it defines (a,b); else
#                        its HINT; else "-".
# Malformed regions (a BEGIN inside a region, an END without a BEGIN, a region
# that never ends) print "starter: FILE:LINE: ..." on stderr and exit 1.

function fail(msg) { printf "starter: %s:%d: %s\n", FILENAME, FNR, msg > "/dev/stderr"; bad = 1; exit 1 }
function defined_name(line,    f) { f = line; sub(/\(.*/, "", f); sub(/.*[ \t*]/, "", f); return f }
function stubbed() { return only != "" ? (count == only + 0) : !keep }
BEGIN {
  n = split(names, pairs, " ")
  for (k = 1; k <= n; k++) { split(pairs[k], kv, "="); doc[kv[1]] = kv[2] }
  if (mode == "") mode = "stub"
  if (keep_below == "") keep_below = 1
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
  in_region = 1; start = FNR; stub = ""; hint = ""; defines = ""; count++
  step = $0; sub(/.*BEGIN SOLUTION step /, "", step); step = substr(step, 1, 2)
  indent = $0; sub(/[^ \t].*/, "", indent)
  keep = (step + 0 < keep_below)
  if (mode == "stub" && !stubbed() && only != "") print
  next
}
/BEGIN SOLUTION/ { fail("expected '/* BEGIN SOLUTION step NN */', found: " $0) }
in_region && /\/\* END SOLUTION \*\// {
  in_region = 0
  if (mode == "list") {
    name = indent == "" ? defines : func_name
    if (name == "") name = hint != "" ? hint : "-"
    printf "%s\t%d\t%d\t%s\t%s\n", FILENAME, start, FNR, step, name
    next
  }
  if (!stubbed()) { if (only != "") print; next }
  if (hint == "") {
    hint = "complete " (func_name != "" ? func_name : "this function")
    if (step in doc) hint = hint " (docs/" doc[step] ".md)"
  }
  print indent "/* TODO(step " step "): " hint " */"
  if (stub != "") print indent stub
  next
}
/END SOLUTION/ { fail("END SOLUTION without a BEGIN") }
in_region && /^[ \t]*\/\* STUB: .*\*\/[ \t]*$/ {
  stub = $0; sub(/^[ \t]*\/\* STUB: /, "", stub); sub(/[ \t]*\*\/[ \t]*$/, "", stub)
  if (mode == "stub" && !stubbed() && only != "") print
  next
}
in_region && /^[ \t]*\/\* HINT: .*\*\/[ \t]*$/ {
  hint = $0; sub(/^[ \t]*\/\* HINT: /, "", hint); sub(/[ \t]*\*\/[ \t]*$/, "", hint)
  if (mode == "stub" && !stubbed() && only != "") print
  next
}
mode == "list" { next }
in_region { if (!stubbed()) print; next }
{ print }
END { if (!bad && in_region) { FNR = start; fail("region never ends (no END SOLUTION)") } }
