#!/usr/bin/env bash
# Every source file of the tree is tracked by git: make starter (and the
# grading's copies) take the files git tracks, so a new file left untracked,
# a shape's common/NAME.c say, gives a starter that does not build while
# make test passes here. Lists each untracked source file (one that
# .gitignore does not ignore) with the command that adds it, and fails.
# Outside a git checkout (a tree from make dist) there is nothing to check.
# docs/extending.md, "Adding a shape".
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "check-tracked: not a git checkout: nothing to check"
  exit 0
fi
untracked=$(git ls-files --others --exclude-standard -- Makefile '*.c' '*.h' '*.mk' '*.sh' \
              '*.awk' '*.scene' '*.md' '*.cases' '*.err' '*.dict')
if [ -z "$untracked" ]; then
  exit 0
fi
echo "check-tracked: source files git does not track (make starter copies only tracked files," \
     "so the starter would lack them):"
while IFS= read -r f; do
  echo "  $f"
done <<< "$untracked"
echo "  add them: git add $(echo $untracked)"
exit 1
