#!/usr/bin/env bash
# The grader's base (docs/grading.md, "How a submission is graded"): from the
# instructor's tree (its files: tools/build/files.sh), the solved tree built with
# the grading flags (its objects seed every scratch build; its binaries
# render the hidden scenes) and the all-stubbed starter (what a missing file
# is graded as); the files that hold solution regions; every test the
# solution runs. In a starter tree (make dist's tarball: no solution in it)
# both are the tree itself, and solution.txt says "none". Cached in
# CACHE/base-KEY, KEY a hash of the tree and flags.
# Usage: tools/grading/base.sh CACHE   (prints the base's folder)
set -euo pipefail

[ $# = 1 ] || { echo "usage: tools/grading/base.sh CACHE" >&2; exit 2; }
. "$(dirname "$0")/../build/files.sh"
top=$(tree_top)
cd "$top"
cache=$(realpath -m -- "$1")
opt=${GRADE_OPT:--O2}
jobs=${GRADE_BUILD_JOBS:-$(nproc)}
mkdir -p "$cache"

# The key: every file of the tree but the prose (*.md), and the flags.
key=$( { tree_files "$top" | grep -zv '\.md$' | xargs -0 sha1sum 2>/dev/null; echo "OPT=$opt"; } |
       sha1sum | cut -c1-16)
dir=$cache/base-$key
exec 9>"$cache/base.lock"
flock 9
if [ -f "$dir/ready" ]; then echo "$dir"; exit 0; fi
rm -rf "$dir" "$cache"/base-*
mkdir -p "$dir"
: >"$dir/tests.tsv"

tools/check/starter.sh "$dir/solved" 9 >/dev/null
tools/check/starter.sh "$dir/stub" 1 >/dev/null
chmod 755 "$dir/solved" "$dir/stub"
rm -rf "$dir/solved/docs/diffs"   # they quote the solution; nothing builds from them

# The files a submission may replace: C sources and headers under common/ and
# steps/ that hold a region (found from the markers, tools/build/files.sh).
region_files "$top" >"$dir/regions.txt"
# A tree with no solution region is a starter: its tests fail where the
# student has not written yet, so their times say nothing of a solution's.
if grep -q . "$dir/regions.txt" && ! xargs grep -l '/\* BEGIN[ ]SOLUTION step' <"$dir/regions.txt" | grep -q .; then
  echo none >"$dir/solution.txt"
  echo "grade: this tree is a starter (no solution regions): submissions are graded against its tests," \
       "reference images and traces; each test may take ${GRADE_UNSOLVED_TEST_MIN:-60} s" >&2
else
  echo solved >"$dir/solution.txt"
fi
echo "grade: preparing the base (the $( [ "$(cat "$dir/solution.txt")" = none ] && echo "starter" ||
  echo "solution") built with OPT=$opt, its tests run) in $dir" >&2

steps=$(cd steps && ls -d [0-9][0-9]-* | sort)
targets=$(for s in $steps; do echo "build/bin/$s build/tests/$s"; done)
# The stress tests render through step 05 and tools/figures/mistakes.c (make test's
# prerequisites).
stress=$(ls tests/stress_*.c >/dev/null 2>&1 && echo build/tests/stress || true)
[ -z "$stress" ] || [ ! -f tools/figures/mistakes.c ] || stress="$stress build/bin/mistakes"
# The reference traces (tests/traces/, make trace-step N), where the tree has them.
traces=$( [ -x tools/figures/traces.sh ] && [ -x tools/build/manifest.sh ] && [ -f tools/loop/trace-diff.c ] &&
          echo build/bin/trace-diff || true)
make -C "$dir/solved" -s -j"$jobs" OPT="$opt" $targets $stress $traces >"$dir/build.log" 2>&1 || {
  echo "grade: the solution does not build with OPT=$opt: see $dir/build.log" >&2; exit 1; }

# Every test of every step (and of the stress suite), as the solution runs
# them: STEP SUITE TEST STATUS SECONDS, tab-separated (tests.tsv). The wall
# time a submission's test program gets: GRADE_SLOWER times the solution's,
# plus a minute (limits.tsv: STEP SECONDS WALL); in a starter, 10 minutes.
. tools/grading/tests.sh
slower=${GRADE_SLOWER:-10}
solution=$(cat "$dir/solution.txt")
# Which programs each step's tests run (runs.tsv: STEP NAME ..., the grader's
# reuse of a step, checks.sh): while they run, each of build/bin/ is a
# wrapper that notes its name, then runs the program.
mkdir -p "$dir/bin.real"
for b in "$dir"/solved/build/bin/*; do
  n=${b##*/}
  mv "$b" "$dir/bin.real/$n"
  printf '#!/bin/bash\n[ -z "${GRADE_RAN:-}" ] || echo %q >>"$GRADE_RAN"\nexec -a "$0" %q "$@"\n' \
    "$n" "$dir/bin.real/$n" >"$b"
  chmod 755 "$b"
done
for s in $steps ${stress:+stress}; do
  (cd "$dir/solved" && GRADE_RAN="$dir/$s.ran" build/tests/$s --jobs 1 --tap="$dir/$s.tap" >"$dir/$s.log" 2>&1) || true
  printf '%s\t%s\n' "$s" "$(sort -u "$dir/$s.ran" 2>/dev/null | tr '\n' ' ')" >>"$dir/runs.tsv"
  tap_times "$dir/$s.tap" | awk -F'\t' -v OFS='\t' -v s="$s" '{ print s, $1, $2, $3, $4 }' >>"$dir/tests.tsv"
  awk -F'\t' -v s="$s" -v k="$slower" -v u="$( [ "$solution" = none ] && echo 600)" \
    '$1 == s { t += $5 } END { printf "%s\t%.2f\t%d\n", s, t, u != "" ? u : 60 + k * t }' "$dir/tests.tsv"
done >"$dir/limits.tsv"
for b in "$dir"/bin.real/*; do mv -f "$b" "$dir/solved/build/bin/${b##*/}"; done
rmdir "$dir/bin.real"
failing=$(awk -F'\t' '$4 != "ok" { print "  " $1 " " $2 "::" $3 }' "$dir/tests.tsv")
if [ -n "$failing" ] && [ "$solution" != none ]; then
  echo "grade: warning: the instructor's solution fails these tests (every submission will too):" >&2
  echo "$failing" >&2
fi
# The steps whose reference traces the solution matches (traces.txt); a
# starter's traces are the solution's, written when it was handed out.
for s in $( [ -n "$traces" ] && echo $steps); do
  tools/build/manifest.sh traces "$s" 2>/dev/null | grep -q . || continue
  if [ "$solution" = none ]; then echo "$s"
  elif (cd "$dir/solved" && tools/figures/traces.sh compare build "$s" >/dev/null 2>&1); then echo "$s"
  else echo "grade: warning: the solution does not match its own reference traces of $s (not graded)" >&2; fi
done >"$dir/traces.txt"
rm -rf "$dir/solved/build/test-out" "$dir/solved/build/diff" "$dir/solved/build/out"
echo "$steps" >"$dir/steps.txt"
echo $targets $stress $traces >"$dir/targets.txt"
touch "$dir/ready"
echo "$dir"
