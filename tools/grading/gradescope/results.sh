#!/usr/bin/env bash
# results.json for Gradescope (its autograder specification) from what
# make grade wrote for one student: a test per check (name, number, score,
# max_score, status, output, visibility), the total, and a summary output.
# Usage: tools/grading/gradescope/results.sh OUT STUDENT SECONDS > results.json
set -euo pipefail

[ $# = 3 ] || { echo "usage: tools/grading/gradescope/results.sh OUT STUDENT SECONDS" >&2; exit 2; }
out=$1 st=$2 d=$1/students/$2
summary=$( {
  echo "Graded $(cut -f1 "$out/points.tsv" | grep -c .) checks; $(awk -F'\t' '$1 == "sandbox" { print $2 }' "$d/info.tsv")."
  awk -F'\t' '$2 == "missing" { print "Not in your submission, graded as the starter'"'"'s stub: " $1 }
              $2 == "changed" { print "Changed in your submission but not used (the course'"'"'s copy is): " $1 }
              $2 == "added" { print "Added in your submission, not used: " $1 }' "$d/files.tsv" 2>/dev/null | head -n 50
  awk -F'\t' '$1 == "stubbed" || $1 == "uncut" { print "Build: " $2 }' "$d/info.tsv"
  if grep -q 'error' "$d/build.log" 2>/dev/null; then
    echo; echo "Build errors:"; grep -E -A3 'error' "$d/build.log" | head -n 40
  fi
} )
# One line per check: CHECK STATUS POINTS MAX WHY, then its details file.
awk -F'\t' -v who="$st" 'FILENAME == ARGV[1] { max[$1] = $2; next }
     $1 == who { printf "%s\t%s\t%s\t%s\t%s\n", $2, $3, $4, max[$2], $5 }' "$out/points.tsv" "$out/scores.tsv" |
while IFS=$'\t' read -r c status pts max why; do
  f=$d/details/$(printf '%s' "$c" | tr '/ ' '__').txt
  jq -n --arg c "$c" --arg s "$status" --argjson p "$pts" --argjson m "$max" --arg why "$why" \
        --rawfile det <( [ -f "$f" ] && head -c 20000 "$f" || true ) \
    '{name: $c, score: $p, max_score: $m, status: (if $s == "PASS" then "passed" else "failed" end),
      output: ($why + (if $det == "" then "" else "\n\n" + $det end)),
      visibility: (if ($c | test("/hidden/")) then "after_due_date" else "visible" end)}'
done | jq -s --arg out "$summary" --argjson t "$3" \
  '{score: (map(.score) | add // 0), execution_time: $t, output: $out, stdout_visibility: "hidden",
    tests: (to_entries | map(.value + {number: ((.key + 1) | tostring)}))}'
