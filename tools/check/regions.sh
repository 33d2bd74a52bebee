#!/usr/bin/env bash
# The solution regions of the tree (C sources and headers under common/ and
# steps/, as git ls-files lists them, with the working tree's content).
# Usage: tools/check/regions.sh list [--tsv]   every region: file, lines, step, function, hash
#        tools/check/regions.sh same           copies of a region in several step folders
#                                        must be the same text (exit 1 otherwise)
# docs/testing-the-tests.md explains both; tools/check/stub.awk finds the regions.
set -euo pipefail

usage() { echo "usage: tools/check/regions.sh list [--tsv] | same" >&2; exit 2; }
top=$(git -C "$(dirname "$0")" rev-parse --show-toplevel 2>/dev/null) || {
  echo "regions: not inside a git checkout (the regions are found from git ls-files)" >&2; exit 1; }
cd "$top"

# One line per region: FILE FIRST LAST STEP NAME HASH (tab-separated). NAME is
# the function the region sits in (tools/check/stub.awk); HASH the first 12 hex
# digits of the SHA-1 of the region's lines, markers and indentation included.
regions_tsv() {
  local f file first last step name hash
  while IFS= read -r -d '' f; do
    [ -e "$f" ] || continue
    grep -q 'BEGIN SOLUTION' "$f" || continue
    awk -v mode=list -f tools/check/stub.awk "$f" | while IFS=$'\t' read -r file first last step name; do
      hash=$(sed -n "${first},${last}p" "$file" | sha1sum | cut -c1-12)
      printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$file" "$first" "$last" "$step" "$name" "$hash"
    done
  done < <(git ls-files -z -- 'common/*.c' 'common/*.h' 'steps/*.c' 'steps/*.h')
}

list() {
  if [ "${1:-}" = --tsv ]; then regions_tsv; return; fi
  printf '%-34s %-9s %-4s %-28s %s\n' file lines step function hash
  regions_tsv | while IFS=$'\t' read -r file first last step name hash; do
    printf '%-34s %-9s %-4s %-28s %s\n' "$file" "$first-$last" "$step" "$name" "$hash"
  done
}

# Regions with the same step label and function in different step folders are
# one piece of student code carried forward: each copy must equal the first.
same() {
  local bad=0 groups=0 copies=0 file first last step name hash key
  declare -A ref
  while IFS=$'\t' read -r file first last step name hash; do
    case "$file" in steps/*) ;; *) continue ;; esac
    key="$step $name"
    if [ -z "${ref[$key]:-}" ]; then
      ref[$key]="$file:$first:$last:$hash"; groups=$((groups + 1)); continue
    fi
    copies=$((copies + 1))
    IFS=: read -r rfile rfirst rlast rhash <<<"${ref[$key]}"
    [ "$hash" = "$rhash" ] && continue
    bad=1
    echo "regions: step $step region of $name differs: $rfile:$rfirst-$rlast and $file:$first-$last"
    diff -u --label "$rfile:$rfirst" --label "$file:$first" \
      <(sed -n "${rfirst},${rlast}p" "$rfile") <(sed -n "${first},${last}p" "$file") \
      | sed -n '3,40p' || true
  done < <(regions_tsv)
  if [ $bad = 0 ]; then
    echo "regions: $copies copies of $groups step-folder regions, all identical to the first"
  fi
  return $bad
}

case "${1:-}" in
  list) shift; [ $# -le 1 ] || usage; list "$@" ;;
  same) [ $# -eq 1 ] || usage; same ;;
  *) usage ;;
esac
