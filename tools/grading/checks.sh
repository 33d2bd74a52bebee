# Sourced by tools/grading/one.sh: the checks of one submission, each a line
# CHECK <tab> PASS|FAIL <tab> why, in RESULTS/checks.tsv; failing tests'
# messages in RESULTS/details/SLUG.txt (docs/grading.md, "Checks").
# Uses: res, name, GRADE_BASE, GRADE_PLAN, GRADE_COMPARE, GRADE_THREADS.

slug() { printf '%s' "$1" | tr '/ ' '__'; }
now() { date +%s.%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

check() { printf '%s\t%s\t%s\n' "$1" "$2" "$3" >>"$res/checks.tsv"; }

# The test suites of STEP in make test-step's order (by name, the image test
# last), as checks: STEP/SUITE.
step_suites() {
  awk -F'\t' -v s="$1" '$1 == s && !seen[$2]++ { print ($2 == "reference_image") "\t" s "/" $2 }' \
    "$GRADE_BASE/tests.tsv" | sort | cut -f2
}

# The checks of STEP: its test suites, its reference traces, its hidden scenes.
step_checks() {
  step_suites "$1"
  grep -qx "$1" "$GRADE_BASE/traces.txt" 2>/dev/null && echo "$1/traces"
  [ -s "$GRADE_PLAN" ] && awk -F'\t' -v s="$1" '$2 == s { print $1 }' "$GRADE_PLAN"
  return 0
}

fail_step() {
  local c
  for c in $(step_checks "$1"); do check "$c" FAIL "$2"; done
}

fail_all() {
  local s
  for s in $(cat "$GRADE_BASE/steps.txt") stress; do fail_step "$s" "$1"; done
}

finish() {
  info seconds "$(seconds_since "$t0")"
  exit 0
}

# take_region_files ROOT TREE LIST: each file that holds a solution region
# from the submission (a regular file, no link) or, when it has none, the
# starter's stub; written into TREE only when it differs from the solved
# tree's copy, so make rebuilds exactly what changed. LIST gets one line per
# file: PATH <tab> taken|missing.
take_region_files() {
  local root=$1 tree=$2 f src
  while read -r f; do
    if safe_file "$root/$f" && [ "$(stat -c %s "$root/$f")" -le 1048576 ]; then
      src=$root/$f; printf '%s\ttaken\n' "$f" >>"$3"
    else
      src=$GRADE_BASE/stub/$f; printf '%s\tmissing\n' "$f" >>"$3"
    fi
    if ! cmp -s "$src" "$tree/$f"; then
      rm -f "$tree/$f" "$tree/build/obj/${f%.*}.o"
      cp "$src" "$tree/$f"
    fi
  done <"$GRADE_BASE/regions.txt"
}

# list_other_changes ROOT LIST: every other file of the submission that is not
# the handed-out one (changed, added, or a link), one line each: PATH <tab>
# changed|added|link. None of them is used. docs/diffs/ (rewritten by make
# diffs), build/ and .git/ are not listed.
list_other_changes() {
  local root=$1 f n=0
  while IFS= read -r -d '' f; do
    f=${f#./}
    grep -qxF -- "$f" "$GRADE_BASE/regions.txt" && continue
    if [ -L "$root/$f" ]; then printf '%s\tlink\n' "$f"
    elif [ ! -e "$GRADE_BASE/stub/$f" ]; then printf '%s\tadded\n' "$f"
    elif ! cmp -s "$root/$f" "$GRADE_BASE/stub/$f" && ! cmp -s "$root/$f" "$GRADE_BASE/solved/$f"; then
      printf '%s\tchanged\n' "$f"
    else continue; fi
    n=$((n + 1)); [ $n -lt 200 ] || break
  done < <(cd "$root" && find . \( -path ./.git -o -path ./build -o -path ./docs/diffs \) -prune \
             -o \( -type f -o -type l \) -print0 2>/dev/null | sort -z) | tr -d '\r' >>"$2"
}

# built TREE STEP: the step's binary and test program (or the stress tests)
# were made by this build.
built() {
  local t=$1
  if [ "$2" = stress ]; then safe_file "$t/build/tests/stress"
  else safe_file "$t/build/tests/$2" && safe_file "$t/build/bin/$2"; fi
}

# The step's tolerance for pictures: its manifest's IMAGE_TOL ("tol fraction
# max", tol and max in 1/255; steps/STEP/step.mk).
step_tolerance() {
  "$GRADE_BASE/solved/tools/manifest.sh" get "$1" IMAGE_TOL
}

# run_traces TREE STEP: the step's reference traces (make trace-step N) in the
# sandbox: the check passes when every traced pixel agrees; the first lines
# that differ are the details.
run_traces() {
  local tree=$1 step=$2 log st
  grep -qx "$step" "$GRADE_BASE/traces.txt" 2>/dev/null || return 0
  log=$res/logs/$step.traces.log
  sandbox_run "${GRADE_TRACE_WALL:-120}" "${GRADE_TRACE_WALL:-120}" "$log" "$tree" -- \
    tools/traces.sh compare build "$step"
  st=$?
  if [ $st = 0 ]; then check "$step/traces" PASS "every reference trace agrees"
  else
    check "$step/traces" FAIL "$( [ $st = 1 ] && echo "a trace differs from the reference (make trace-step ${step%%-*})" ||
      echo "the traces $(sandbox_status_text $st "${GRADE_TRACE_WALL:-120}" "${GRADE_TRACE_WALL:-120}")")"
    head -n 60 "$log" >"$res/details/$(slug "$step/traces").txt"
  fi
}

# compare MODE ARGS...: the grader's picture comparison, outside the sandbox,
# under limits; prints its one line of results.
compare() {
  timeout 60 prlimit --as=$((2048 << 20)) -- "$GRADE_COMPARE" "$@" 2>>"$res/compare.log"
}

# image_pictures TREE STEP: expected | yours | difference for the image test's
# render (build/test-out/STEP.pfm), with its worst pixel. The verdict is the
# image test's own.
image_pictures() {
  local tree=$1 step=$2 out line
  out=$tree/build/test-out/$step.pfm
  safe_file "$out" || return 0
  line=$(compare exact $(step_tolerance "$step") "$res/pictures/$(slug "$step/reference_image")" "$out" \
           "$GRADE_BASE/solved/images/$step.png") || return 0
  printf '%s/reference_image\t%s\n' "$step" "$line" >>"$res/pictures.tsv"
}

# run_hidden TREE STEP: each hidden scene of STEP (GRADE_PLAN: CHECK STEP
# SCENE MODE SEED COST REFS), rendered by the submission's binary in the
# sandbox (GRADE_SLOWER times the solution's time, at least GRADE_RENDER_MIN,
# 5 s) and compared with the solution's render(s).
run_hidden() {
  local tree=$1 step=$2 c s scene mode seed cost refs out line st wall
  [ -s "$GRADE_PLAN" ] || return 0
  while IFS=$'\t' read -r c s scene mode seed cost refs; do
    [ "$s" = "$step" ] || continue
    wall=${GRADE_RENDER_WALL:-$(awk -v c="$cost" -v k="${GRADE_SLOWER:-10}" -v n="$GRADE_THREADS" \
      -v m="${GRADE_RENDER_MIN:-5}" 'BEGIN { w = k * c / n; printf "%d", w < m ? m : w + 1 }')}
    out=$tree/.grade-out/$(slug "$c").pfm
    cp "$scene" "$tree/.grade-out/scene.scene" && sandbox_own "$tree/.grade-out"
    sandbox_run "$wall" $((wall * GRADE_THREADS)) "$res/logs/$(slug "$c").log" "$tree" -- \
      "build/bin/$step" --scene .grade-out/scene.scene --threads "$GRADE_THREADS" --seed "$seed" \
      --quiet -o "$out"
    st=$?
    if [ $st != 0 ] || ! safe_file "$out"; then
      check "$c" FAIL "the render $(sandbox_status_text $st "$wall" $((wall * GRADE_THREADS)))$(
        [ $st = 0 ] && echo " but wrote no picture")"
      continue
    fi
    if [ "$mode" = noise ]; then
      line=$(compare noise "${GRADE_NOISE_RATIO:-2.5}" "$res/pictures/$(slug "$c")" "$out" $refs)
    else
      line=$(compare exact $(step_tolerance "$step") "$res/pictures/$(slug "$c")" "$out" $refs)
    fi
    hidden_verdict "$c" "$mode" "$line"
  done <"$GRADE_PLAN"
}

# hidden_verdict CHECK MODE LINE: the check from grade-compare's line.
hidden_verdict() {
  local c=$1 line=$3
  [ -n "$line" ] || { check "$c" FAIL "the render could not be compared (compare.log)"; return; }
  printf '%s\t%s\n' "$c" "$line" >>"$res/pictures.tsv"
  local kv; declare -A v; for kv in $line; do v[${kv%%=*}]=${kv#*=}; done
  local why
  if [ "${v[reason]:-}" = size ]; then why="the render is ${v[yours]}, expected ${v[expected]}"
  elif [ "$2" = noise ]; then
    why="bias against ${v[seeds]} solution renders: ${v[ratio]} times the solution's own level (allowed ${v[allowed]}); rms difference ${v[rmse]}/255, the solution's noise ${v[noise]}/255"
  else
    why="${v[over]} channels over ${v[tol]}/255 ($(awk -v f="${v[fraction]}" 'BEGIN { printf "%.3f", 100 * f }')%, allowed $(awk -v f="${v[allowed_fraction]}" 'BEGIN { printf "%.3f", 100 * f }')%), max ${v[max]}/255 (allowed ${v[allowed_max]}/255)"
  fi
  if [ "${v[pass]}" = 1 ]; then check "$c" PASS "$why"; else check "$c" FAIL "$why"; fi
}
