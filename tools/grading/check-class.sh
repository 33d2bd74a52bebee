#!/usr/bin/env bash
# make test-grade's check of the grader on the sample class (docs/grading.md,
# "The sample class"): every submission of tools/grading/sample-class.txt must
# fail exactly the checks its "fails:" line names (a pattern, or !pattern for
# checks it passes among those), and its total in grades.csv must be the
# maximum less the points of those checks, and the "total:" line's where it
# has one.
# Usage: tools/grading/check-class.sh OUT   (OUT: where make grade wrote)
set -uo pipefail
set -f   # the patterns are matched against check names, never against files

[ $# = 1 ] || { echo "usage: tools/grading/check-class.sh OUT" >&2; exit 2; }
out=$1
list=$(cd "$(dirname "$0")" && pwd)/sample-class.txt
bad=0

# The expected failures of each submission: NAME <tab> patterns <tab> total.
# A "fails:" line may go on over the indented lines after it.
expected=$(awk 'function flush() { if (name != "") print name "\t" f "\t" t; name = "" }
                /^[ \t]+fails:/ { sub(/^[ \t]*fails:[ \t]*/, ""); f = $0; more = 1; next }
                /^[ \t]+total:/ { t = $2; more = 0; next }
                /^[ \t]+[^ \t]/ && more { f = f " " $0; next }
                /^[^ \t#]/ { flush(); name = $1; f = ""; t = ""; more = 0 }
                END { flush() }' "$list" | tr -s ' ')
max=$(awk -F'\t' '{ s += $2 } END { print s + 0 }' "$out/points.tsv")

while IFS=$'\t' read -r name patterns total_want; do
  if [ ! -f "$out/students/$name/checks.tsv" ]; then
    echo "check-class: $name: not graded (no $out/students/$name/checks.tsv)"; bad=1; continue
  fi
  # The checks the patterns name, among all checks of the class.
  want=$(cut -f1 "$out/points.tsv" | while read -r c; do
           hit=0
           for p in $patterns; do
             case $p in -) ;; !*) [[ "$c" == ${p#!} ]] && { hit=0; break; } ;; *) [[ "$c" == $p ]] && hit=1 ;; esac
           done
           [ $hit = 0 ] || echo "$c"
         done | sort)
  got=$(awk -F'\t' '$2 != "PASS" { print $1 }' "$out/students/$name/checks.tsv" | sort)
  missing=$(cut -f1 "$out/points.tsv" | sort | comm -23 - <(cut -f1 "$out/students/$name/checks.tsv" | sort))
  lost=$(for c in $want; do awk -F'\t' -v c="$c" '$1 == c { print $2 }' "$out/points.tsv"; done |
         awk '{ s += $1 } END { print s + 0 }')
  total=$(awk -F, -v n="$name" '$1 == n { print $(NF - 1) }' "$out/grades.csv")
  if [ "$want" != "$got" ] || [ -n "$missing" ]; then
    echo "check-class: $name: expected to fail: $(echo $want)"
    echo "check-class: $name: failed:           $(echo $got)"
    [ -z "$missing" ] || echo "check-class: $name: checks never graded: $(echo $missing)"
    bad=1
  elif [ "$total" != "$((max - lost))" ]; then
    echo "check-class: $name: total $total in grades.csv, expected $max - $lost"; bad=1
  elif [ -n "$total_want" ] && [ "$total" != "$total_want" ]; then
    echo "check-class: $name: total $total in grades.csv, expected $total_want (its total: line)"; bad=1
  else
    echo "check-class: $name: $total / $max, fails exactly: $(echo ${want:--})"
  fi
done <<<"$expected"
n_expected=$(printf '%s\n' "$expected" | grep -c .)
n_graded=$(ls "$out/students" | grep -c .)
[ "$n_expected" = "$n_graded" ] || { echo "check-class: $n_graded graded, $n_expected in $list"; bad=1; }
exit $bad
