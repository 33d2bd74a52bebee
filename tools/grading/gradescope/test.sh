#!/usr/bin/env bash
# make test-grade's check of the Gradescope autograder (docs/grading.md,
# "Gradescope"): the zip of make gradescope unpacked into a temporary root
# (AUTOGRADER_ROOT), setup.sh and run_autograder run there on one submission
# of the sample class, and results.json checked against the fields of
# Gradescope's autograder specification; its score must be the one make
# grade gave the same submission (grades.csv).
# Usage: tools/grading/gradescope/test.sh CLASS OUT STUDENT
#   CLASS: the sample class; OUT: where make grade graded it; STUDENT: a folder entry
set -euo pipefail

[ $# = 3 ] || { echo "usage: tools/grading/gradescope/test.sh CLASS OUT STUDENT" >&2; exit 2; }
class=$(realpath -- "$1") out=$(realpath -- "$2") st=$3
. "$(dirname "$0")/../../build/files.sh"
top=$(tree_top)
cd "$top"
root=$(mktemp -d "${TMPDIR:-/tmp}/autograder.XXXXXX")
trap 'rm -rf "$root"' EXIT
fail() { echo "gradescope test: $*" >&2; exit 1; }

tools/grading/gradescope/zip.sh "$root/autograder.zip" tools/grading/sample-hidden >/dev/null
mkdir -p "$root/source" "$root/submission"
(cd "$root/source" && unzip -q ../autograder.zip)
# This checkout's build of the library, so that setup.sh builds grade-compare
# from it rather than from scratch (the same files, the same flags).
mkdir -p "$root/source/course/build/bin"
for f in .deps .flags config.mk obj libcommon.a bin/grade-compare; do
  [ ! -e "build/$f" ] || cp -a "build/$f" "$root/source/course/build/$f"
done
cp -a "$class/$st/." "$root/submission/"
export AUTOGRADER_ROOT=$root GRADE_CACHE=$out/cache
"$root/source/setup.sh" >"$root/setup.log" 2>&1 || { cat "$root/setup.log" >&2; fail "setup.sh failed"; }
"$root/source/run_autograder" >"$root/run.log" 2>&1 || { cat "$root/run.log" >&2; fail "run_autograder failed"; }
json=$root/results/results.json
[ -f "$json" ] || fail "run_autograder wrote no $json"

# The specification's fields, their types and allowed values.
jq -e '
  def num: type == "number";
  def vis: . == "hidden" or . == "after_due_date" or . == "after_published" or . == "visible";
  (.score | num) and (.execution_time | num) and (.output | type == "string") and
  (.stdout_visibility | vis) and (.tests | type == "array" and length > 0) and
  (.tests | all(
     (.name | type == "string") and (.number | type == "string") and (.score | num) and
     (.max_score | num) and .score >= 0 and .score <= .max_score and
     (.status == "passed" or .status == "failed") and (.output | type == "string") and (.visibility | vis) and
     (.max_score == 0 or ((.status == "passed") == (.score == .max_score))))) and
  (.tests | all(if (.name | test("/hidden/")) then .visibility == "after_due_date" else .visibility == "visible" end)) and
  (.score == (.tests | map(.score) | add)) and
  ((.tests | map(.name) | unique | length) == (.tests | length))' "$json" >/dev/null ||
  fail "$json does not follow Gradescope's specification: $(jq -c '.tests[0]' "$json" 2>&1 | head -c 400)"
want=$(awk -F, -v n="$st" '$1 == n { print $(NF - 1) }' "$out/grades.csv")
got=$(jq '.score' "$json")
checks=$(cut -f1 "$out/points.tsv" | grep -c .)
[ "$(jq '.tests | length' "$json")" = "$checks" ] || fail "results.json has $(jq '.tests | length' "$json") tests, make grade $checks checks"
[ "$got" = "$want" ] || fail "results.json gives $st $got points, make grade gave $want"
echo "gradescope test: results.json follows the specification: $st $got / $(jq '[.tests[].max_score] | add' "$json") points," \
     "$(jq '[.tests[] | select(.visibility == "after_due_date")] | length' "$json") hidden-scene tests after the due date"
