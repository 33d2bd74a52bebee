# Sourced by tools/check/starter.sh and the grader (tools/grading/grade, tools/grading/,
# tools/grading/gradescope/): the course tree's files, with or without git.
# In a git checkout they are the tracked files (git ls-files, with the working
# tree's content, deleted ones left out); in a copy without git (the tarball
# of make dist, a Gradescope upload) every file but build/ and .git.

# tree_top: the tree that holds this script (the folder above tools/).
tree_top() { (cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd -P); }

# tree_is_git TOP: TOP is the top of a git checkout (not a folder inside one).
tree_is_git() {
  [ "$(git -C "$1" rev-parse --show-toplevel 2>/dev/null)" = "$1" ]
}

# tree_files TOP: its files, relative to TOP, NUL-separated, sorted.
tree_files() {
  local top=$1 f
  if tree_is_git "$top"; then
    git -C "$top" ls-files -z | while IFS= read -r -d '' f; do
      [ -e "$top/$f" ] && printf '%s\0' "$f"
    done
  else
    (cd "$top" && find . \( -path ./build -o -path ./.git \) -prune -o \( -type f -o -type l \) -print0 |
      sed -z 's|^\./||' | sort -z)
  fi
}

# region_files TOP: the C sources and headers under common/ and steps/ that
# hold a region a student writes: an instructor's solution region
# (BEGIN SOLUTION) or, in a starter, the student's markers (BEGIN step NN:),
# one a line, sorted. Found from the markers, so a region moved to a new file
# is found there.
region_files() {
  local top=$1
  tree_files "$top" | grep -zE '^(common|steps)/.*\.[ch]$' |
    (cd "$top" && xargs -0 -r grep -lE '/\* BEGIN (SOLUTION step [0-9]{2} \*/|step [0-9]{2}: )') | sort
}
