#!/usr/bin/env bash
# The Gradescope autograder (docs/grading.md, "Gradescope"): ZIP holds
# setup.sh and run_autograder at its root, the course tree (its files,
# tools/build/files.sh: git ls-files in a checkout) in course/, the hidden scenes in
# hidden/ and the points scheme as points.txt.
# Usage: tools/grading/gradescope/zip.sh ZIP [HIDDEN] [POINTS]
set -euo pipefail

[ $# -ge 1 ] && [ $# -le 3 ] || { echo "usage: tools/grading/gradescope/zip.sh ZIP [HIDDEN] [POINTS]" >&2; exit 2; }
zip_path=$(realpath -m -- "$1")
hidden=${2:-}
points=${3:-tools/grading/points.txt}
. "$(dirname "$0")/../../build/files.sh"
top=$(tree_top)
[ -z "$hidden" ] || hidden=$(realpath -- "$hidden")
points=$(realpath -- "$points")
cd "$top"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/gradescope.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
tree_files "$top" | while IFS= read -r -d '' f; do
  mkdir -p "$tmp/course/$(dirname "$f")" && cp -p "$f" "$tmp/course/$f"
done
cp -p tools/grading/gradescope/setup.sh tools/grading/gradescope/run_autograder "$tmp/"
cp "$points" "$tmp/points.txt"
if [ -n "$hidden" ]; then mkdir -p "$tmp/hidden" && cp "$hidden"/*.scene "$tmp/hidden/"; fi
mkdir -p "$(dirname "$zip_path")"
rm -f "$zip_path"
(cd "$tmp" && zip -qr "$zip_path" .)
echo "gradescope: wrote $zip_path ($(du -h "$zip_path" | cut -f1)): upload it as the assignment's autograder"
