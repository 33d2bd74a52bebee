#!/usr/bin/env bash
# Gradescope's image setup (docs/grading.md, "Gradescope"): runs once, as
# root, when Gradescope builds the autograder's image from autograder.zip
# (make gradescope writes it). Installs the Debian/Ubuntu packages through the
# course's own install step, as the Dockerfile does (make grade-deps: make
# deps, tools/build/deps.sh, then the grader's) and builds the grader's base and
# the hidden scenes' solution renders, so that each submission only builds its
# own files, and grades the solution and the untouched starter (whose results
# a submission's unchanged steps take). course/ needs no git (tools/build/files.sh
# lists its files).
# AUTOGRADER_ROOT (default /autograder) moves the whole layout, for tests.
set -euo pipefail

root=${AUTOGRADER_ROOT:-/autograder}
src=$root/source
cd "$src/course"
if ! command -v make >/dev/null; then
  echo "setup: installing Debian's make (apt-get)"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq make >/dev/null
fi
make -s grade-deps
make -s build/bin/grade-compare
# What run_autograder grades with, prepared: the base, the hidden scenes'
# renders, the solution and the untouched starter graded.
args=(OUT="$root/grade/out" JOBS=1)
[ -d "$src/hidden" ] && args+=(HIDDEN="$src/hidden")
[ -f "$src/points.txt" ] && args+=(POINTS="$src/points.txt")
GRADE_CACHE=${GRADE_CACHE:-$root/cache} tools/grading/grade --prepare "${args[@]}"
echo "setup: the grader is ready in ${GRADE_CACHE:-$root/cache}"
