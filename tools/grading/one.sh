#!/usr/bin/env bash
# Grade one submission (docs/grading.md, "How a submission is graded"): a
# scratch tree from the grader's base with only the files that hold solution
# regions taken from the submission, built and tested under limits in the
# sandbox, its hidden-scene renders compared with the solution's. Writes
# RESULTS/checks.tsv (CHECK, PASS or FAIL, why), the failing tests' messages,
# the pictures and notes that tools/grading/report.sh turns into pages.
# Usage: tools/grading/one.sh CONFIG SUBMISSION   (CONFIG: written by tools/grading/grade)
set -uo pipefail

[ $# = 2 ] || { echo "usage: tools/grading/one.sh CONFIG SUBMISSION" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
. "$1"
. "$here/sandbox.sh"
. "$here/unpack.sh"
. "$here/checks.sh"
. "$here/tests.sh"

sub=$2
name=$(submission_name "$sub")
res=$GRADE_OUT/students/$name
rm -rf "$res"
mkdir -p "$res/pictures" "$res/details" "$GRADE_OUT/work"
work=$(mktemp -d "$GRADE_OUT/work/$name.XXXXXX")
chmod 755 "$work"
[ -n "${GRADE_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
t0=$(now)
sandbox_init
info() { printf '%s\t%s\n' "$1" "$2" >>"$res/info.tsv"; }
info name "$name"
info source "$sub"
info sandbox "$SANDBOX_WHY"
info host "$(hostname)"

# ---------------------------------------------------------------- the tree
kind=$(submission_kind "$sub")
info kind "$kind"
tree=$work/tree
if ! submission_open "$sub" "$kind" "$work/sub" "$res/open.log"; then
  info opened no
  fail_all "the submission could not be opened: $(tail -n 1 "$res/open.log")"
  finish
fi
root=$(submission_root "$work/sub/files")
cp -a "$GRADE_BASE/solved/." "$tree"
rm -rf "$tree/build/bin" "$tree/build/tests" "$tree/build/libcommon.a"
take_region_files "$root" "$tree" "$res/files.tsv"
list_other_changes "$root" "$res/files.tsv"
mkdir -p "$tree/.grade-out"
sandbox_own "$tree"

# ---------------------------------------------------------------- build
tb=$(now)
sandbox_run "${GRADE_BUILD_WALL:-600}" "${GRADE_BUILD_CPU:-600}" "$res/build.log" "$tree" -- \
  make -k -j"$GRADE_THREADS" OPT="$GRADE_OPT" $(cat "$GRADE_BASE/targets.txt")
st=$?
info build "$(sandbox_status_text $st "${GRADE_BUILD_WALL:-600}" "${GRADE_BUILD_CPU:-600}")"

# ---------------------------------------------------------------- steps cut
# A step is graded by the build that made its programs. Where the whole
# submission did not build one, the step takes the build of the submission's
# regions of steps up to M, the later steps' regions the starter's stubs
# (tools/grading/cut.awk), for the highest M from the step's own up that
# builds it: a region that does not compile costs its own step and the later
# ones only (docs/grading.md, "How a submission is graded").
declare -A tree_of
need=()
for step in $(cat "$GRADE_BASE/steps.txt") stress; do
  grep -q "^$step	" "$GRADE_BASE/tests.tsv" || continue
  if built "$tree" "$step"; then tree_of[$step]=$tree; else need+=("$step"); fi
done
[ ${#need[@]} = 0 ] || [ "$st" -ge 124 ] || cut_builds
info build_seconds "$(seconds_since "$tb")"

# ---------------------------------------------------------------- checks
# A step whose programs are those of a step graded before takes its results
# (checks.sh, "reuse").
reused=""
HASHES=$work/hashes
mkdir -p "$HASHES"
for step in $(cat "$GRADE_BASE/steps.txt") stress; do
  grep -q "^$step	" "$GRADE_BASE/tests.tsv" || continue
  if [ -n "${tree_of[$step]:-}" ]; then
    step_tree=${tree_of[$step]}
    key=$(step_key "$step_tree" "$step")
    if step_reuse "$key" "$step"; then
      reused="$reused${reused:+ }$step"
      continue
    fi
    ts=$(now)
    run_tests "$step_tree" "$step"
    info "tests_seconds $step" "$(seconds_since "$ts")"
    ts=$(now)
    [ "$step" = stress ] || { run_traces "$step_tree" "$step"; image_pictures "$step_tree" "$step"; run_hidden "$step_tree" "$step"; }
    info "hidden_seconds $step" "$(seconds_since "$ts")"
    step_save "$key" "$step"
  else
    fail_step "$step" "did not build (the build log says why)"
  fi
done
info reused "${reused:+the same programs as graded before, their results taken: }${reused:-none}"
finish
