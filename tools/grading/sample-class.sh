#!/usr/bin/env bash
# The sample class (docs/grading.md, "The sample class"): one submission per
# entry of tools/grading/sample-class.txt, each the solved starter tree with
# realistic mistakes applied by tools/check/mutate.sh, handed in the way the entry
# says (a folder, a git working tree, .tar.gz, .zip, a git bundle, a bare git
# repository).
# Usage: tools/grading/sample-class.sh DIR   (DIR is emptied, then filled)
set -euo pipefail

[ $# = 1 ] || { echo "usage: tools/grading/sample-class.sh DIR" >&2; exit 2; }
. "$(dirname "$0")/../build/files.sh"
top=$(tree_top)
cd "$top"
[ -x tools/check/mutate.sh ] || { echo "sample-class: tools/check/mutate.sh is missing (make mutants brings it)" >&2; exit 1; }
out=$(realpath -m -- "$1")
list=tools/grading/sample-class.txt
tmp=$(mktemp -d "${TMPDIR:-/tmp}/sample-class.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# git with a fixed author and date, so that the class is the same every time.
g() {
  GIT_AUTHOR_NAME=student GIT_AUTHOR_EMAIL=student@example.org GIT_AUTHOR_DATE='2025-01-01T12:00:00Z' \
  GIT_COMMITTER_NAME=student GIT_COMMITTER_EMAIL=student@example.org GIT_COMMITTER_DATE='2025-01-01T12:00:00Z' \
    git -c init.defaultBranch=main -c core.hooksPath=/dev/null "$@"
}
commit_all() { g -C "$1" init -q && g -C "$1" add -A && g -C "$1" commit -qm "my ray tracer"; }

# The solved tree every submission starts from, and the starters it may stop at.
tools/check/starter.sh "$tmp/solved" 9 >/dev/null
rm -rf "$out"
mkdir -p "$out"
n=0
while IFS= read -r line; do
  case $line in ''|'#'*|[[:space:]]*) continue ;; esac   # comments, "fails:" lines
  read -r name form mutants <<<"$line"
  tree=$tmp/work/$name
  mkdir -p "$tmp/work"
  rm -rf "$tree"
  if [[ "$mutants" == starter:* ]]; then
    tools/check/starter.sh "$tree" "${mutants#starter:}" >/dev/null
  else
    cp -a "$tmp/solved" "$tree"
    if [ "$mutants" != - ]; then
      for m in ${mutants//+/ }; do tools/check/mutate.sh "$m" "$tree" >/dev/null; done
    fi
  fi
  case $form in
    folder) mv "$tree" "$out/$name" ;;
    git-folder) commit_all "$tree" && mv "$tree" "$out/$name" ;;
    tar.gz) tar -czf "$out/$name.tar.gz" -C "$tmp/work" "$name" ;;
    zip) (cd "$tmp/work" && zip -qr "$out/$name.zip" "$name") ;;
    bundle) commit_all "$tree" && g -C "$tree" bundle create -q "$out/$name.bundle" HEAD main ;;
    bare) commit_all "$tree" && g clone -q --bare "$tree" "$out/$name.git" ;;
    *) echo "sample-class: $list: $name: unknown form '$form'" >&2; exit 1 ;;
  esac
  n=$((n + 1))
done <"$list"
echo "sample-class: wrote $n submissions to $out"
