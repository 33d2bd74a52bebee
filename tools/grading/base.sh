#!/usr/bin/env bash
# The grader's base (docs/grading.md, "How a submission is graded"): from the
# instructor's tree (the tracked files, git ls-files), the solved tree built
# with the grading flags (its objects seed every scratch build; its binaries
# render the hidden scenes) and the all-stubbed starter (what a missing file
# is graded as); the files that hold solution regions; every test the
# solution runs. Cached in CACHE/base-KEY, KEY a hash of the tree and flags.
# Usage: tools/grading/base.sh CACHE   (prints the base's folder)
set -euo pipefail

[ $# = 1 ] || { echo "usage: tools/grading/base.sh CACHE" >&2; exit 2; }
top=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
cd "$top"
cache=$(realpath -m -- "$1")
opt=${GRADE_OPT:--O2}
jobs=${GRADE_BUILD_JOBS:-$(nproc)}
mkdir -p "$cache"

# The key: every tracked file but the prose (*.md), and the flags.
key=$( { git ls-files -z -- . ':!:*.md' | xargs -0 sha1sum 2>/dev/null; echo "OPT=$opt"; } |
       sha1sum | cut -c1-16)
dir=$cache/base-$key
exec 9>"$cache/base.lock"
flock 9
if [ -f "$dir/ready" ]; then echo "$dir"; exit 0; fi
rm -rf "$dir" "$cache"/base-*
mkdir -p "$dir"
: >"$dir/tests.tsv"
echo "grade: preparing the base (the solution built with OPT=$opt, its tests run) in $dir" >&2

tools/starter.sh "$dir/solved" 9 >/dev/null
tools/starter.sh "$dir/stub" 1 >/dev/null
chmod 755 "$dir/solved" "$dir/stub"
rm -rf "$dir/solved/docs/diffs"   # they quote the solution; nothing builds from them

# The files a submission may replace: C sources and headers under common/ and
# steps/ that hold a solution region.
git ls-files -z -- 'common/*.c' 'common/*.h' 'steps/*.c' 'steps/*.h' |
  xargs -0 grep -l '/\* BEGIN[ ]SOLUTION step [0-9][0-9] \*/' | sort >"$dir/regions.txt"

steps=$(cd steps && ls -d [0-9][0-9]-* | sort)
targets=$(for s in $steps; do echo "build/bin/$s build/tests/$s"; done)
# The stress tests render through step 05 and tools/mistakes.c (make test's
# prerequisites).
stress=$(ls tests/stress_*.c >/dev/null 2>&1 && echo build/tests/stress || true)
[ -z "$stress" ] || [ ! -f tools/mistakes.c ] || stress="$stress build/bin/mistakes"
# The reference traces (tests/traces/, make trace-step N), where the tree has them.
traces=$( [ -x tools/traces.sh ] && [ -x tools/manifest.sh ] && [ -f tools/trace-diff.c ] &&
          echo build/bin/trace-diff || true)
make -C "$dir/solved" -s -j"$jobs" OPT="$opt" $targets $stress $traces >"$dir/build.log" 2>&1 || {
  echo "grade: the solution does not build with OPT=$opt: see $dir/build.log" >&2; exit 1; }

# Every test of every step (and of the stress suite), as the solution runs
# them: STEP SUITE TEST STATUS SECONDS, tab-separated (tests.tsv). The wall
# time a submission's test program gets: GRADE_SLOWER times the solution's,
# plus a minute (limits.tsv: STEP SECONDS WALL).
. tools/grading/tests.sh
slower=${GRADE_SLOWER:-10}
for s in $steps ${stress:+stress}; do
  (cd "$dir/solved" && build/tests/$s --jobs 1 --tap="$dir/$s.tap" >"$dir/$s.log" 2>&1) || true
  tap_times "$dir/$s.tap" | awk -F'\t' -v OFS='\t' -v s="$s" '{ print s, $1, $2, $3, $4 }' >>"$dir/tests.tsv"
  awk -F'\t' -v s="$s" -v k="$slower" '$1 == s { t += $5 } END { printf "%s\t%.2f\t%d\n", s, t, 60 + k * t }' \
    "$dir/tests.tsv"
done >"$dir/limits.tsv"
failing=$(awk -F'\t' '$4 != "ok" { print "  " $1 " " $2 "::" $3 }' "$dir/tests.tsv")
if [ -n "$failing" ]; then
  echo "grade: warning: the instructor's solution fails these tests (every submission will too):" >&2
  echo "$failing" >&2
fi
# The steps whose reference traces the solution matches (traces.txt).
for s in $( [ -n "$traces" ] && echo $steps); do
  tools/manifest.sh traces "$s" 2>/dev/null | grep -q . || continue
  if (cd "$dir/solved" && tools/traces.sh compare build "$s" >/dev/null 2>&1); then echo "$s"
  else echo "grade: warning: the solution does not match its own reference traces of $s (not graded)" >&2; fi
done >"$dir/traces.txt"
rm -rf "$dir/solved/build/test-out" "$dir/solved/build/diff" "$dir/solved/build/out"
echo "$steps" >"$dir/steps.txt"
echo $targets $stress $traces >"$dir/targets.txt"
touch "$dir/ready"
echo "$dir"
