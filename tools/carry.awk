# The student's regions of a C source file of a starter tree, for
# tools/carry.sh (docs/instructors.md, "Carrying code forward").
# tools/stub.awk writes them:
#   <indent>/* BEGIN step NN: NAME */
#   ...the student's code (at first a TODO(step NN) line and a stub)...
#   <indent>/* END step NN */
# NAME is the function the region sits in (or the functions a region at file
# scope defines in the solution); "NN: NAME" is the region's key, with " #k"
# added to the k-th of several equal ones.
#
# Variables (awk -v):
#   mode=list     one line per region: FIRST <tab> LAST <tab> STEP <tab> KEY
#                 <tab> TODO (1 when a TODO(step NN) line is still inside)
#   mode=replace  copy the file, the body of the i-th region replaced by the
#     repl=DIR    content of DIR/i when that file exists
# Malformed markers print "carry: FILE:LINE: ..." on stderr and exit 1.

function fail(msg) { printf "carry: %s:%d: %s\n", FILENAME, FNR, msg > "/dev/stderr"; bad = 1; exit 1 }
FNR == 1 { in_region = 0; count = 0; delete seen }
/^[ \t]*\/\* BEGIN step [0-9][0-9]: .* \*\/[ \t]*$/ {
  if (in_region) fail("a BEGIN step marker inside the region that starts on line " start " (its END step " step " line is missing)")
  in_region = 1; start = FNR; todo = 0; count++
  key = $0; sub(/^[ \t]*\/\* BEGIN step /, "", key); sub(/ \*\/[ \t]*$/, "", key)
  step = substr(key, 1, 2)
  if (++seen[key] > 1) key = key " #" seen[key]
  if (mode == "replace") {
    print
    file = repl "/" count
    replacing = (getline line < file) > 0
    if (replacing) { print line; while ((getline line < file) > 0) print line; close(file) }
  }
  next
}
/^[ \t]*\/\* END step [0-9][0-9] \*\/[ \t]*$/ {
  if (!in_region) fail("an END step marker without its BEGIN step line")
  end_step = $0; sub(/^[ \t]*\/\* END step /, "", end_step); end_step = substr(end_step, 1, 2)
  if (end_step != step) fail("END step " end_step " closes the region of step " step " that starts on line " start)
  in_region = 0
  if (mode == "list") printf "%d\t%d\t%s\t%s\t%d\n", start, FNR, step, key, todo
  else print
  next
}
/\/\* (BEGIN|END) step [0-9]/ { fail("a changed marker line (expected /* BEGIN step NN: NAME */ or /* END step NN */): " $0) }
in_region && /TODO\(step [0-9][0-9]\)/ { todo = 1 }
mode == "replace" && !(in_region && replacing) { print }
END { if (!bad && in_region) { FNR = start; fail("the region of step " step " never ends (its /* END step " step " */ line is missing)") } }
