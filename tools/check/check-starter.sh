#!/usr/bin/env bash
# The starter tree, played by a student (make check-starter; CI runs it):
#   1. make starter (every step stubbed) builds, every TODO line cites a doc
#      section that exists, and make test-step K fails for every K;
#   2. then, for K = 1 .. 8, the student writes step K's regions, each once
#      where the starter has its TODO line (the solution's code: write_step):
#      make test-step K must pass and make test-step K+1 fail.
#      --full: every step at every stage (steps 1..K pass, K+1..8 fail);
#   3. with every step written, the student's make test passes (step 8's
#      test-step is part of it).
# Usage: tools/check/check-starter.sh DIR [--full]   (DIR is removed and rewritten)
# docs/instructors.md, "Checks of the starter".
set -uo pipefail
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "usage: tools/check/check-starter.sh DIR [--full]" >&2; exit 2; }
dir=$1 full=${2:-}
top=$(cd "$(dirname "$0")/../.." && pwd)
start=$(date +%s)
log=$(mktemp "${TMPDIR:-/tmp}/check-starter.XXXXXX")
trap 'rm -f "$log"' EXIT
bad=0

say() { echo "check-starter: $*"; }
fail() { say "FAIL: $*"; bad=$((bad + 1)); }
show_log() { sed -n '/FAIL\|fail\|rror\|expected\|got\|read /p' "$log" | head -n 20 | sed 's/^/    /'; }
# test_step K pass|fail: make test-step K in the starter must pass (or fail).
# Built with -O1 without LTO in a folder of its own (as check-regions'
# scratch tree is): each stage then recompiles the files it wrote and relinks
# cheaply, where an LTO link optimises every program again. The starter's
# build with the default flags is checked once, first. Only the verdicts
# count: a failing image test does not render the Phong terms (RT_TERMS=0,
# tests/terms.h).
QUICK="BUILD=build/quick OPT=-O1"
test_step() {
  local k=$1 want=$2 rc
  # shellcheck disable=SC2086 # QUICK is two words on purpose
  RT_TERMS=0 make -C "$dir" --no-print-directory -j2 $QUICK test-step "$k" >"$log" 2>&1
  rc=$?
  if [ "$want" = pass ] && [ $rc -ne 0 ]; then
    fail "make test-step $k should pass (steps 1..$stage written), it fails:"; show_log
  elif [ "$want" = fail ] && [ $rc -eq 0 ]; then
    fail "make test-step $k should fail (step $k not written), it passes"
  fi
}

# write_step K: step K's regions written as the student writes them: each
# file that holds a region made again from the solution with the steps up to
# K solved (tools/check/stub.awk, as make starter N=K+1 writes it); a file left as
# it was when nothing in it changed.
declare -A step_name
for s in "$top"/steps/[0-9][0-9]-*/; do s=${s%/}; s=${s##*/}; step_name[${s%%-*}]=$s; done
names=$(for k in "${!step_name[@]}"; do printf '%s=%s ' "$k" "${step_name[$k]}"; done)
write_step() {
  local f new
  while IFS= read -r f; do
    new=$(awk -v keep_below=$(($1 + 1)) -v names="$names" -f "$top/tools/check/stub.awk" "$top/$f") || return 1
    [ "$new" = "$(cat "$dir/$f")" ] || printf '%s\n' "$new" > "$dir/$f"
  done < <(cd "$top" && grep -l -r --include='*.[ch]' 'BEGIN SOLUTION' common steps | sort)
}

tools_starter=$top/tools/check/starter.sh
"$tools_starter" "$dir" >/dev/null || exit 1
dir=$(cd "$dir" && pwd)
if ! make -C "$dir" -j2 build >"$log" 2>&1; then
  fail "the starter does not build:"; tail -n 20 "$log" | sed 's/^/    /'; exit 1
fi
say "the starter builds ($(grep -rhoE --include='*.[ch]' '/\* BEGIN step [0-9]{2}: ' "$dir/common" "$dir/steps" | grep -c .) regions stubbed)"
# The TODO lines' doc sections (the rest is make check-refs's, in the tree).
(cd "$dir" && tools/check/check-refs.sh >"$log" 2>&1)
todo_refs=$(while IFS=: read -r _ file line rest; do
  [ -n "$line" ] && sed -n "${line}p" "$dir/$file" 2>/dev/null | grep -q 'TODO(step' && echo "    $file:$line:$rest"
done < <(grep '^check-refs: [^ ]*:[0-9]*:' "$log" | sed 's/^check-refs: /x:/'))
[ -z "$todo_refs" ] || { fail "TODO lines cite doc sections that do not exist:"; echo "$todo_refs"; }

stage=0
before=$bad
for k in 1 2 3 4 5 6 7 8; do test_step $k fail; done
[ $bad -eq $before ] && say "no step written: make test-step 1 .. 8 all fail"

for stage in 1 2 3 4 5 6 7 8; do
  write_step $stage || { fail "could not write step $stage's regions"; break; }
  before=$bad
  if [ -n "$full" ]; then
    for k in 1 2 3 4 5 6 7 8; do test_step $k "$([ $k -le $stage ] && echo pass || echo fail)"; done
    [ $bad -eq $before ] && say "steps 1..$stage written: make test-step 1..$stage pass, the others fail"
  elif [ $stage -lt 8 ]; then
    test_step $stage pass
    test_step $((stage + 1)) fail
    [ $bad -eq $before ] && say "steps 1..$stage written: make test-step $stage passes, $((stage + 1)) fails"
  fi
  [ $stage -eq 8 ] && all_written=1
done

# Every step written: the student's make test (every step's tests, step 8's
# included, then the stress, reliability and trace tests) must pass.
if [ "${all_written:-0}" = 1 ]; then
  t0=$(date +%s)
  # shellcheck disable=SC2086 # QUICK is two words on purpose
  if RT_TERMS=0 make -C "$dir" --no-print-directory -j2 $QUICK test >"$log" 2>&1; then
    say "steps 1..8 written: make test passes ($(( $(date +%s) - t0 )) s)"
  else
    fail "make test should pass (steps 1..8 written), it fails:"; show_log
  fi
fi

if [ $bad -gt 0 ]; then
  say "$bad problem(s) ($(( $(date +%s) - start )) s)"
  exit 1
fi
say "ok ($(( $(date +%s) - start )) s)"
