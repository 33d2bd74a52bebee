#!/usr/bin/env bash
# make regen: rebuild every derived file, write only those whose content
# changed beyond its check's own tolerance, then list what was written and
# the hand-written places that name what changed (docs/instructors.md,
# "Derived files").
# Usage: tools/figures/regen.sh BUILD STEP...   (the Makefile builds the programs first)
# The environment: REGEN_ONLY="diffs images traces docimg" (a part of them:
# make images, make traces, make diffs, make docimg), REGEN_BENCH=1 (make bench
# too: docs/benchmarks.md), REGEN_HOOKS (make targets of other generators, from
# mk/regen.mk; each prints "regen: wrote FILE", or "TOOL: rewrote FILE", for a
# file it writes).
# Its own parts, in order:
#   diffs   docs/diffs/NN-name.diff          tools/figures/diffs.sh write (text: byte for byte)
#   images  images/NN-name[.TERM].png       tools/figures/images.sh write (any pixel)
#   traces  tests/traces/NN-name/X_Y.json   tools/figures/traces.sh write (trace-diff's tolerance)
#   docimg  docs/img/**.png                 tools/figures/docimg.sh write (any pixel)
set -uo pipefail
build=${1:?usage: tools/figures/regen.sh BUILD STEP...}; shift
steps=("$@")
here=$(dirname "$0")
export REGEN_DIR=$build/regen
mkdir -p "$REGEN_DIR"
log=$REGEN_DIR/written
: > "$log"
parts=${REGEN_ONLY:-diffs images traces docimg}

# run PART COMMAND...: its "regen: " lines kept in the log, the rest shown.
run() {
  local part=$1 st; shift
  echo "regen: $part"
  # A hook's "TOOL: rewrote FILE" counts as "regen: wrote FILE".
  "$@" 2>&1 | sed -u 's/^[^ ]*: rewrote /regen: wrote /' | tee -a "$log.raw" |
    { grep --line-buffered '^regen: \(wrote\|removed\) ' >> "$log" || true; }
  st=${PIPESTATUS[0]}
  grep -v '^regen: \(wrote\|removed\) ' "$log.raw" | sed 's/^/  /'; : > "$log.raw"
  [ "$st" = 0 ] || { echo "regen: $part failed (exit $st)"; failed=1; }
}
failed=0
: > "$log.raw"
for p in $parts; do
  case $p in
    diffs)  run diffs  "$here/diffs.sh" write "${steps[@]}" ;;
    images) run images "$here/images.sh" write "$build" "${steps[@]}" ;;
    traces) run traces "$here/traces.sh" write "$build" "${steps[@]}" ;;
    docimg) run docimg "$here/docimg.sh" write "$build" ;;
    *) echo "regen: unknown part '$p' (diffs images traces docimg)" >&2; exit 2 ;;
  esac
done
if [ -z "${REGEN_ONLY:-}" ]; then
  for t in ${REGEN_HOOKS:-}; do run "$t" make --no-print-directory "$t"; done
  [ "${REGEN_BENCH:-}" = 1 ] && run bench make --no-print-directory bench
fi

# The scene (or other source) each written file is derived from.
source_of() {
  local f=$1 s xy opts
  case $f in
    images/*) s=${f#images/}; s=${s%%.*}; "$here/../build/manifest.sh" get "$s" SCENE ;;
    tests/traces/*/*.json)
      s=${f#tests/traces/}; s=${s%%/*}; xy=${f##*/}; xy=${xy%.json}
      opts=$("$here/../build/manifest.sh" traces "$s" | awk -F'|' -v p="${xy/_/ }" '$1 == p { print $2 }')
      if [[ $opts =~ --scene\ ([^ ]+) ]]; then echo "${BASH_REMATCH[1]}"
      else "$here/../build/manifest.sh" get "$s" SCENE; fi ;;
    docs/img/*) awk -F'\t' -v f="$f" '$1 == f { print $2 }' "$REGEN_DIR/docimg.sources" 2>/dev/null ;;
    docs/diffs/*) ;;   # from the steps' code: no scene to name
    *) echo "(its generator's sources)" ;;
  esac
}

n=$(wc -l < "$log")
if [ "$n" = 0 ]; then
  echo "make regen: every derived file is up to date (nothing written)"
else
  echo "make regen: wrote $n file(s):"
  sed 's/^regen: /  /' "$log"
fi
# The sources: of what was written, and every scene changed since the last commit.
while read -r _ _ f _; do printf '%s\t%s\n' "$(source_of "$f")" "$f"; done < "$log" > "$REGEN_DIR/from"
# The sources whose lines changed since the last commit: the places to re-read.
changed=$(git diff -U0 HEAD -- 'scenes/*.scene' 'steps/*/step.mk' 'tests/traces/*.scene' 2>/dev/null |
          awk '/^diff --git/ { f = $4; sub(/^b\//, "", f) } /^-[^-]/ && !/^-[ \t]*#/ && f { print f; f = "" }')
untouched=$(cut -f1 "$REGEN_DIR/from" | awk -v c="$changed" '
  BEGIN { n = split(c, a, "\n"); for (k = 1; k <= n; k++) skip[a[k]] = 1 } NF && !seen[$0]++ && !skip[$0]')
if [ -n "$untouched" ]; then
  echo
  echo "Derived from a source unchanged since the last commit (the code moved them; nothing to re-read):"
  paste -sd' ' <<<"$untouched" | fold -s -w 96 | sed 's/^/  /'
fi
if [ -n "$changed" ]; then
  echo
  echo "Derived from -> the hand-written places that name what changed (re-read them):"
  while IFS= read -r src; do
    "$here/regen-places.sh" "$src" "$(awk -F'\t' -v s="$src" '$1 == s { print $2 }' "$REGEN_DIR/from")"
  done <<<"$changed"
fi
exit $failed
