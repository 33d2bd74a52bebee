#!/usr/bin/env bash
# Gradescope's image setup (docs/grading.md, "Gradescope"): runs once, as
# root, when Gradescope builds the autograder's image from autograder.zip
# (make gradescope writes it). Installs the Debian/Ubuntu packages through the
# course's own install step, as the Dockerfile does (make grade-deps: make
# deps, tools/deps.sh, then the grader's), makes course/ a git checkout (the grader reads git
# ls-files), and builds the grader's base and the hidden scenes' solution
# renders, so that each submission only builds its own files.
# AUTOGRADER_ROOT (default /autograder) moves the whole layout, for tests.
set -euo pipefail

root=${AUTOGRADER_ROOT:-/autograder}
src=$root/source
cd "$src/course"
if ! command -v make >/dev/null || ! command -v git >/dev/null; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq make git >/dev/null
fi
if [ ! -d .git ]; then
  git init -q && git add -A &&
    git -c user.name=grader -c user.email=grader@localhost commit -qm "course tree" --no-gpg-sign
fi
make -s grade-deps
make -s build/bin/grade-compare
cache=${GRADE_CACHE:-$root/cache}
base=$(tools/grading/base.sh "$cache")
if [ -d "$src/hidden" ]; then
  tools/grading/hidden.sh "$base" "$src/hidden" "$cache" >/dev/null
fi
echo "setup: the grader's base is ready in $base"
