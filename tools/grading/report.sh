#!/usr/bin/env bash
# The grader's outputs (docs/grading.md, "Outputs"), from what
# tools/grading/one.sh left in OUT/students/*: OUT/points.tsv (every check and
# its points), OUT/grades.csv (a row per student, a column per check, the
# total), a page per student and the class page OUT/index.html. Static pages,
# no script, the pictures beside them.
# Usage: tools/grading/report.sh OUT POINTS
set -euo pipefail

[ $# = 2 ] || { echo "usage: tools/grading/report.sh OUT POINTS" >&2; exit 2; }
out=$1 points=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$out/config.sh"
. "$here/checks.sh"
. "$here/html.sh"

# Every check, in order, with its points (the first matching rule), or 0 with
# the word "starter" when the untouched starter passes it (GRADE_REF: tools/grading/grade).
starter_checks=${GRADE_REF:+$GRADE_REF/students/stub/checks.tsv}
for s in $(cat "$GRADE_BASE/steps.txt") stress; do step_checks "$s"; done |
  awk -v scheme="$points" -v starter="${starter_checks:-/dev/null}" '
    BEGIN {
      while ((getline line < scheme) > 0) {
        sub(/#.*/, "", line); k = split(line, g, " ")
        if (k == 0) continue
        if (k != 2 || g[2] !~ /^[0-9]+(\.[0-9]+)?$/) { print scheme ": expected CHECK POINTS, found: " line > "/dev/stderr"; exit 2 }
        re = g[1]; gsub(/[.+^$(){}|\[\]\\]/, "\\\\&", re); gsub(/\*/, ".*", re); gsub(/\?/, ".", re)
        rule[++r] = "^" re "$"; pts[r] = g[2]
      }
      while ((getline line < starter) > 0) { split(line, g, "\t"); if (g[2] == "PASS") given[g[1]] = 1 }
    }
    { p = 0; for (i = 1; i <= r; i++) if ($0 ~ rule[i]) { p = pts[i]; break }
      if ($0 in given) print $0 "\t0\tstarter"; else print $0 "\t" p }
  ' >"$out/points.tsv"

students=$(cd "$out/students" 2>/dev/null && ls | sort || true)

# The points a student got for each check: STUDENT CHECK STATUS POINTS WHY.
for st in $students; do
  awk -F'\t' -v who="$st" 'FILENAME == ARGV[1] { p[$1] = $2; order[++n] = $1; if ($3 == "starter") given[$1] = 1; next }
       { v[$1] = $2; why[$1] = $3 }
       END { for (i = 1; i <= n; i++) { c = order[i]; s = (c in v) ? v[c] : "FAIL"
               printf "%s\t%s\t%s\t%s\t%s%s\n", who, c, s, s == "PASS" ? p[c] : 0,
                      (c in v) ? why[c] : "not graded (the grader stopped before this check)",
                      (c in given) ? " (worth 0: the untouched starter passes it too)" : "" } }' \
    "$out/points.tsv" "$out/students/$st/checks.tsv" 2>/dev/null ||
  awk -F'\t' -v who="$st" '{ printf "%s\t%s\tFAIL\t0\tnot graded\n", who, $1 }' "$out/points.tsv"
done >"$out/scores.tsv"

# grades.csv: student, one column per check (points earned), total, max.
{
  printf 'student'; cut -f1 "$out/points.tsv" | sed 's/^/,/' | tr -d '\n'; echo ',total,max'
  awk -F'\t' -v max="$(awk -F'\t' '{ s += $2 } END { print s + 0 }' "$out/points.tsv")" '
    $1 != who { if (who != "") print row "," tot "," max; who = $1; row = who; tot = 0 }
    { row = row "," $4; tot += $4 }
    END { if (who != "") print row "," tot "," max }' "$out/scores.tsv"
} >"$out/grades.csv"

for st in $students; do student_page "$out" "$st" >"$out/students/$st/index.html"; done
class_page "$out" >"$out/index.html"
