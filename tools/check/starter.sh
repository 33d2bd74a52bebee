#!/usr/bin/env bash
# Write the student starter tree: the tree's files (git ls-files in a
# checkout, every file in a copy without git: tools/build/files.sh) copied to DIR,
# every solution region replaced by a TODO(step NN) line and its stub between
# /* BEGIN step NN: FUNCTION */ and /* END step NN */.
# Usage: tools/check/starter.sh DIR [N]   (N: keep the solutions of steps below N)
# docs/instructors.md, "The starter tree", explains the regions and what a student gets.
set -euo pipefail

usage() { echo "usage: tools/check/starter.sh DIR [N]   (N = 1 .. 8: steps below N stay solved)" >&2; exit 2; }
[ $# -ge 1 ] && [ $# -le 2 ] && [ -n "$1" ] || usage
dir=$1
keep_below=${2:-1}
[[ "$keep_below" =~ ^[0-9]+$ ]] && [ $((10#$keep_below)) -ge 1 ] && [ $((10#$keep_below)) -le 9 ] || usage
keep_below=$((10#$keep_below))

dir=$(realpath -m -- "$dir")   # relative to where the script was called from
. "$(dirname "$0")/../build/files.sh"
top=$(tree_top)
cd "$top"
# DIR is removed and rewritten: never the checkout, a parent of it, or a
# tracked folder; inside the checkout only under build/.
case "$dir/" in
  "$top"/build/?*) ;;
  "$top"/*) echo "starter: refusing to write over '$dir': use a folder under build/ or outside the checkout" >&2; exit 1 ;;
esac
case "$top/" in "$dir"/*) echo "starter: refusing to write over '$dir': it contains the checkout" >&2; exit 1 ;; esac

# Step number -> folder name (01 -> 01-film), for the docs page in each TODO.
declare -A step_name
for s in steps/[0-9][0-9]-*/; do s=${s%/}; s=${s#steps/}; step_name[${s%%-*}]=$s; done
names=$(for k in "${!step_name[@]}"; do printf '%s=%s ' "$k" "${step_name[$k]}"; done)

# tools/check/stub.awk replaces each region of a step >= keep by its TODO line and
# stub, and keeps the solution of a step below keep, both between the
# student's markers.
stub_awk="$top/tools/check/stub.awk"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/starter.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
regions=0; files=0
while IFS= read -r -d '' f; do
  # The mutants' 'from' texts quote the solution: instructors only.
  case "$f" in tools/check/mutants/*) continue ;; esac
  mkdir -p "$tmp/tree/$(dirname "$f")"
  # Regions live in C sources; docs and diffs only quote them (the diffs are
  # rewritten below from the stubbed steps).
  case "$f" in *.c|*.h) is_c=1 ;; *) is_c=0 ;; esac
  if [ $is_c = 1 ] && grep -q 'BEGIN SOLUTION' "$f" 2>/dev/null; then
    awk -v keep_below="$keep_below" -v names="$names" -f "$stub_awk" "$f" > "$tmp/tree/$f"
    chmod --reference="$f" "$tmp/tree/$f"
    regions=$((regions + $(grep -c 'BEGIN SOLUTION' "$f"))); files=$((files + 1))
  else
    cp -p "$f" "$tmp/tree/$f"
  fi
done < <(tree_files "$top")

# The starter keeps -Werror, except for what a stub leaves unused (parameters,
# variables, static helpers the solution called): still shown as warnings, they
# point at what the student has to use.
sed -i 's/^\(WERROR *?= *-Werror\)$/\1 -Wno-error=unused-parameter -Wno-error=unused-variable -Wno-error=unused-function -Wno-error=unused-but-set-variable/' \
  "$tmp/tree/Makefile"
grep -q -- '^WERROR .*-Wno-error=unused-parameter' "$tmp/tree/Makefile" || {
  echo "starter: could not relax -Werror in the starter's Makefile" >&2; exit 1; }
# Its consecutive-step diffs show the stubs, not the solutions.
if [ -x "$tmp/tree/tools/figures/diffs.sh" ]; then
  (cd "$tmp/tree" && tools/figures/diffs.sh write $(ls -d steps/[0-9][0-9]-* | sed 's|steps/||') >/dev/null)
fi

rm -rf "$dir"
mkdir -p "$(dirname "$dir")"
mv "$tmp/tree" "$dir"
left=$(grep -rl 'BEGIN SOLUTION' "$dir" --include='*.c' --include='*.h' || true)
[ -z "$left" ] || { echo "starter: solution markers left in: $left" >&2; exit 1; }
echo "starter: wrote $dir ($regions solution regions in $files files;" \
     "$( [ "$keep_below" -gt 1 ] && echo "steps below $keep_below kept solved" || echo "all stubbed" )). Build it: cd $dir && make"
