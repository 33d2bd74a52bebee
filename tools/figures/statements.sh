#!/usr/bin/env bash
# The files generated from the parser's statement table (the STATEMENTS
# table of common/app/parser_state.c, and the light types of
# common/app/light_statement.c), read back from the messages a step binary
# prints for an unknown word, as a user sees them:
#   - the lists in the expected messages: "expected a statement (film, ...)"
#     and "expected a light type (point, ...)" in tests/bad/scenes/*.err and
#     in docs/scene-format.md's examples;
#   - tests/statements.h, the same lists for the tests written in C;
#   - the keywords of tests/fuzz/scene.dict (its kw_ lines): every
#     statement, light type and keyword.
# Only files whose content changes are written, and each is named.
#
#   tools/figures/statements.sh BINARY           rewrite them (make regen-statements)
#   tools/figures/statements.sh --check BINARY   say which are stale, exit 1 if any
#                                        (make check-statements)
#
# BINARY is any step's program (build/bin/01-film). docs/extending.md,
# "Adding a shape".
set -euo pipefail

check=0
if [ "${1:-}" = --check ]; then
  check=1
  shift
fi
bin=${1:?usage: tools/figures/statements.sh [--check] STEP-BINARY}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The list in the message for a scene of one line `$1`, after "expected
# $2 (": the words between the parentheses, or nothing.
listed() {
  printf '%s\n' "$1" > "$tmp/probe.scene"
  { "$bin" --quiet --scene "$tmp/probe.scene" -o "$tmp/probe.png" 2>&1 >/dev/null || true; } |
    sed -n "s/.*: expected $2 (\([^)]*\)), found .*/\1/p" | head -n 1
}

statements=$(listed teapot 'a statement')
kinds=$(listed 'light teapot' 'a light type')
if [ -z "$statements" ] || [ -z "$kinds" ]; then
  echo "tools/figures/statements.sh: $bin printed no list of statements or light types" >&2
  exit 2
fi

# Every word of the format, each once, in the order the lists give them: a
# statement, then its keywords (read from its unknown-keyword message, the
# keyword given first or after a name); then each light type and its own.
keywords() {
  local k
  k=$(listed "$1 teapot" "an\? [a-z ]*keyword")
  [ -n "$k" ] || k=$(listed "$1 x teapot" "an\? [a-z ]*keyword")
  printf '%s\n' "${k//, /$'\n'}"
}
words=$(
  {
    for s in ${statements//,/}; do
      echo "$s"
      [ "$s" = light ] || keywords "$s"
    done
    for t in ${kinds//,/}; do
      echo "$t"
      keywords "light $t"
    done
  } | awk 'NF && !seen[$0]++'
)

stale=0
# Put $tmp/new in place of file $1 when it differs.
update() {
  if cmp -s "$tmp/new" "$1"; then
    return
  fi
  if [ $check = 1 ]; then
    echo "$1: stale (the parser's lists of statements changed)"
    stale=1
  else
    cp "$tmp/new" "$1"
    echo "tools/figures/statements.sh: rewrote $1"
  fi
}

for f in tests/bad/scenes/*.err docs/scene-format.md; do
  sed -e "s/expected a statement ([^)]*)/expected a statement ($statements)/g" \
      -e "s/expected a light type ([^)]*)/expected a light type ($kinds)/g" "$f" > "$tmp/new"
  update "$f"
done

cat > "$tmp/new" <<HEADER
/* The lists an unknown word's message gives, for the tests' expected
 * messages. Generated from the parser's statement table by
 * tools/figures/statements.sh (make regen-statements); do not edit. */
#ifndef RT_TEST_STATEMENTS_H
#define RT_TEST_STATEMENTS_H

#define STATEMENTS \\
  "($statements)"
#define LIGHT_TYPES "($kinds)"

#endif
HEADER
update tests/statements.h

dict=tests/fuzz/scene.dict
awk -v words="$words" '
  /^kw_/ { if (!done) { n = split(words, w, "\n"); for (i = 1; i <= n; i++)
                          printf "kw_%s=\"%s \"\n", w[i], w[i]; done = 1 }
           next }
  { print }' "$dict" > "$tmp/new"
update "$dict"

if [ $stale = 1 ]; then
  echo "the files generated from the statement table are stale: run make regen"
  exit 1
fi
