#!/usr/bin/env bash
# Every file a source, test, tool or doc cites exists, and every doc section
# cited as `docs/NN-name.md, "Section"` or `README.md, "Section"` (comments,
# TODO lines, tests/check.h's CHECK(fn, doc) strings, messages, the reference
# traces' "doc" fields, the expected error messages) is a heading of that doc:
# the heading itself, or a heading that starts with it ("What you write" names
# "## What you write (the solution regions)"). `README, "Section"` and
# `README "Section"` are read as README.md's. Usage: tools/check/check-refs.sh (make
# check-refs, part of make check-derived); exit 1, with one line per broken
# reference, when some are.
# Scanned: the tracked C sources, headers, scripts, makefiles, Markdown files,
# reference traces (tests/traces/), expected messages (tests/bad/), mutants
# (tools/check/mutants/) and the report's page: every path under docs/, common/,
# steps/, tests/, tools/, bench/, scenes/, images/, mk/ they mention, the
# docs' relative links, and section citations.
set -uo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"

listed() { # the tracked files; in a copy without git (a starter), every file
  if [ "$(git rev-parse --show-toplevel 2>/dev/null)" = "$top" ]; then
    git ls-files -- "$@"
  else
    local p; for p in "$@"; do find . -path ./build -prune -o -type f -name "${p##*/}" -print; done | sed 's|^\./||'
  fi
}

# One citation per line: FILE <tab> LINE <tab> KIND <tab> TARGET [<tab> SECTION].
# KIND: "path" (a path a source mentions), "link" (a Markdown link, relative
# to its doc), "section" (DOC.md, "Section").
read -r -d '' cites <<'AWK' || true
function emit(kind, target) { printf "%s\t%d\t%s\t%s\n", FILENAME, FNR, kind, target }
BEGIN { md = 0 }
FNR == 1 { md = FILENAME ~ /\.md$/ }
md && /^[ \t]*```/ { fence = !fence; next }
# A path in a source or a doc, never build/, a pattern (NN-name, STEP_NAME, test_<x>,
# $x, %s, *.c) or a Markdown link a script writes ("](bench/x.png)", relative
# to the doc it writes).
{
  line = $0
  while (match(line, /(docs|common|fast|steps|tests|tools|bench|scenes|images|mk)\/[A-Za-z0-9_.\/+-]*/)) {
    pre = RSTART > 1 ? substr(line, RSTART - 1, 1) : ""
    pre2 = RSTART > 2 ? substr(line, RSTART - 2, 2) : ""
    tok = substr(line, RSTART, RLENGTH); nextc = substr(line, RSTART + RLENGTH, 1)
    line = substr(line, RSTART + RLENGTH)
    if (pre ~ /[A-Za-z0-9_.\/-]/) continue   # inside a longer path (build/tests/...)
    sub(/[.+-]+$/, "", tok)
    if (nextc ~ /[$%<{*[]/ || tok ~ /NN|[A-Z][A-Z]/ || pre2 == "](") continue
    emit("path", tok)
  }
}
# A Markdown link [text](target) outside code blocks: not a URL, not an anchor.
md && !fence {
  line = $0
  while (match(line, /\]\([^) \t]+\)/)) {
    tok = substr(line, RSTART + 2, RLENGTH - 3); line = substr(line, RSTART + RLENGTH)
    if (tok ~ /^(https?:|mailto:|#)/) continue
    sub(/#.*/, "", tok)
    emit("link", tok)
  }
}
# For DOC.md, "Section": the lines joined, comment leaders and \" escapes
# dropped, so that a citation may wrap (code blocks of a doc left out).
!fence {
  text = $0
  if (!md) { sub(/^[ \t]*(\/\*+|\*|\/\/|#)[ \t]?/, "", text); gsub(/\\"/, "\"", text) }
  n++; at[n] = length(joined) + 1; lineno[n] = FNR
  joined = joined text " "
}
END {
  rest = joined; off = 0
  while (match(rest, /[A-Za-z0-9_.\/-]+\.md,[ \t]+"[^"]+"|README,?[ \t]+"[^"]+"/)) {
    cite = substr(rest, RSTART, RLENGTH); pos = off + RSTART
    off += RSTART + RLENGTH - 1; rest = substr(rest, RSTART + RLENGTH)
    doc = cite; sub(/,?[ \t]+".*/, "", doc)
    if (doc == "README") doc = "README.md"
    sec = cite; sub(/^[^"]*"/, "", sec); sub(/"$/, "", sec); gsub(/[ \t]+/, " ", sec)
    if (doc ~ /NN|%|\*|\$/ || doc == "DOC.md" || sec == "Section") continue
    for (k = n; k > 1 && at[k] > pos; k--) ;
    printf "%s\t%d\tsection\t%s\t%s\n", FILENAME, lineno[k], doc, sec
  }
}
AWK

# The headings of a Markdown file, outside code blocks, without the #s.
headings() { awk '/^[ \t]*```/ { f = !f; next } !f && /^#+[ \t]/ { sub(/^#+[ \t]+/, ""); sub(/[ \t#]+$/, ""); print }' "$1"; }

bad=0
report() { echo "check-refs: $*"; bad=$((bad + 1)); }
while IFS= read -r f; do
  [ -f "$f" ] && awk "$cites" "$f"
done < <(listed '*.c' '*.h' '*.sh' '*.awk' '*.mk' 'Makefile' '.ci/run' '*.md' '*.json' '*.err' \
            '*.mut' '*.html' 'tools/grading/grade' 'tools/grading/gradescope/run_autograder' 'Dockerfile' |
           sort -u) > "${TMPDIR:-/tmp}/cites.$$"
while IFS=$'\t' read -r file line kind target section; do
  case $kind in
    path) # a program is named after its source (bench/gen_spheres.c)
      [ -e "$target" ] || [ -e "$target.c" ] || [ "$target" = tools/starter-regions.tsv ] ||
        report "$file:$line: cites $target: no such file" ;;
    link)
      [ -e "$(dirname "$file")/$target" ] || report "$file:$line: links to $target: no such file" ;;
    section)
      doc=$target
      [ -e "$doc" ] || doc=$(dirname "$file")/$target   # a doc citing its neighbour
      if [ ! -f "$doc" ]; then report "$file:$line: cites $target, \"$section\": no such file"; continue; fi
      headings "$doc" | awk -v s="$section" '
        { h = $0; gsub(/`/, "", h) }
        h == s || (index(h, s) == 1 && substr(h, length(s) + 1, 1) !~ /[A-Za-z0-9]/) { found = 1 }
        END { exit !found }' ||
        report "$file:$line: cites $target, \"$section\": no such heading (its sections: $(headings "$doc" | sed -n '2,$p' | paste -sd ';' | sed 's/;/; /g'))" ;;
  esac
done < "${TMPDIR:-/tmp}/cites.$$"
rm -f "${TMPDIR:-/tmp}/cites.$$"
if [ $bad -gt 0 ]; then
  echo "check-refs: $bad broken reference(s)"
  exit 1
fi
echo "check-refs: every cited file and doc section exists"
