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

# step_number STEP: the step's number (08); the stress tests' is the highest
# of the steps whose programs they run (GRADE_BASE/runs.tsv).
step_number() {
  if [ "$1" != stress ]; then echo "${1%%-*}"; return; fi
  awk -F'\t' '$1 == "stress" { print $2 }' "$GRADE_BASE/runs.tsv" 2>/dev/null | tr ' ' '\n' |
    sed -n 's/^\([0-9][0-9]\)-.*/\1/p' | sort | tail -n 1 | grep . || tail -n 1 "$GRADE_BASE/steps.txt" | cut -c1-2
}

# cut_builds: the steps of need[] (not built from the whole submission), each
# given the build of the submission's regions of steps up to M and the
# starter's stubs for later ones (tools/grading/cut.awk), M from the highest
# step down; a step takes the first such build, with M at least its own
# number, that makes its programs (tree_of[STEP]). A cut the previous one's
# compile errors do not touch is not built again. A file whose markers do not
# pair with the starter's is taken whole. Uses tree, work, res, need, tree_of.
cut_builds() {
  local m s f prev=$tree prev_used=1 vt changed errs left uncut="" used steps_cut=""
  for m in $(cut -c1-2 "$GRADE_BASE/steps.txt" | sort -r); do
    left=0
    for s in "${need[@]}"; do [ -n "${tree_of[$s]:-}" ] || [ "$(step_number "$s")" -gt "$m" ] || left=1; done
    [ $left = 1 ] || continue
    vt=$work/upto-$m
    mkdir -p "$vt.files"
    changed=()
    while IFS=$'\t' read -r f how; do
      [ "$how" = taken ] || continue
      mkdir -p "$vt.files/$(dirname "$f")"
      if ! awk -v upto="$m" -f "$here/cut.awk" "$GRADE_BASE/stub/$f" "$tree/$f" >"$vt.files/$f" 2>/dev/null; then
        cp "$tree/$f" "$vt.files/$f"
        case " $uncut " in *" $f "*) ;; *) uncut="$uncut${uncut:+ }$f" ;; esac
      fi
      cmp -s "$vt.files/$f" "$prev/$f" || changed+=("$f")
    done <"$res/files.tsv"
    # The same files, or the last build's errors all in region files this
    # cut leaves as they were: the same errors again.
    errs=$(sed -n 's/^\([^ :]*\.[ch]\):[0-9][0-9]*:\([0-9][0-9]*:\)\{0,1\} \(fatal \)\{0,1\}error:.*/\1/p' \
             "$( [ "$prev" = "$tree" ] && echo "$res/build.log" || echo "$res/logs/build.upto-${prev##*-}.log")" | sort -u)
    if [ ${#changed[@]} = 0 ] || { [ -n "$errs" ] && ! grep -vqxF -f "$GRADE_BASE/regions.txt" <<<"$errs" &&
                                     ! printf '%s\n' "${changed[@]}" | grep -qxF -f <(echo "$errs"); }; then
      rm -rf "$vt.files"; continue
    fi
    # A cut tree that graded no step is rebuilt in place.
    if [ "$prev_used" = 0 ]; then mv "$prev" "$vt"; else cp -a "$prev" "$vt"; fi
    for f in "${changed[@]}"; do
      rm -f "$vt/$f" "$vt/build/obj/${f%.*}.o"
      cp "$vt.files/$f" "$vt/$f"
    done
    rm -rf "$vt.files"
    sandbox_own "$vt"
    mkdir -p "$res/logs"
    sandbox_run "${GRADE_BUILD_WALL:-600}" "${GRADE_BUILD_CPU:-600}" "$res/logs/build.upto-$m.log" "$vt" -- \
      make -k -j"$GRADE_THREADS" OPT="$GRADE_OPT" $(cat "$GRADE_BASE/targets.txt")
    [ $? -lt 124 ] || break
    used=0
    for s in "${need[@]}"; do
      [ -z "${tree_of[$s]:-}" ] && [ "$(step_number "$s")" -le "$m" ] && built "$vt" "$s" || continue
      tree_of[$s]=$vt used=1 steps_cut="$steps_cut${steps_cut:+ }$s:$m"
    done
    prev=$vt prev_used=$used
  done
  [ -z "$steps_cut" ] || info stubbed "$(cut_words "$steps_cut")"
  [ -z "$uncut" ] || info uncut "$uncut: its region markers differ from the starter's, so it was taken whole for every step"
  return 0
}

# cut_words "STEP:M ...": the page's words for the steps graded with later
# regions stubbed.
cut_words() {
  local s m last="" list="" out=""
  for s in $1; do
    m=${s#*:}
    if [ "$m" != "$last" ] && [ -n "$list" ]; then out="$out${out:+; }$(cut_sentence "$list" "$last")"; list=""; fi
    list="$list${list:+, }${s%:*}" last=$m
  done
  out="$out${out:+; }$(cut_sentence "$list" "$last")"
  echo "the whole submission did not build: $out"
}
cut_sentence() {
  local later
  later=$(cut -c1-2 "$GRADE_BASE/steps.txt" | awk -v m="$2" '$1 + 0 > m + 0 { s[++n] = $1 }
    END { for (k = 1; k <= n; k++) printf "%s%s", k == 1 ? "" : k == n ? " and " : ", ", s[k] }')
  echo "$1 graded with your regions of steps $(head -n 1 "$GRADE_BASE/steps.txt" | cut -c1-2) to $2" \
       "and the starter's stubs for step$( [ "${later#* }" = "$later" ] || echo s) $later"
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
  "$GRADE_BASE/solved/tools/build/manifest.sh" get "$1" IMAGE_TOL
}

# run_traces TREE STEP: the step's reference traces (make trace-step N) in the
# sandbox: the check passes when every traced pixel agrees; the first lines
# that differ are the details.
run_traces() {
  local tree=$1 step=$2 log st
  grep -qx "$step" "$GRADE_BASE/traces.txt" 2>/dev/null || return 0
  log=$res/logs/$step.traces.log
  sandbox_run "${GRADE_TRACE_WALL:-120}" "${GRADE_TRACE_WALL:-120}" "$log" "$tree" -- \
    tools/figures/traces.sh compare build "$step"
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
    wall=$(hidden_wall "$cost")
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

# hidden_wall COST: the wall-time limit of a hidden render that took the
# solution COST seconds of one thread.
hidden_wall() {
  echo "${GRADE_RENDER_WALL:-$(awk -v c="$1" -v k="${GRADE_SLOWER:-10}" -v n="$GRADE_THREADS" \
    -v m="${GRADE_RENDER_MIN:-5}" 'BEGIN { w = k * c / n; printf "%d", w < m ? m : w + 1 }')}"
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

# ---------------------------------------------------------------- reuse
# A step's verdicts depend only on the programs that run in it (its test
# program, its binary, the programs its tests ran when the solution was
# tested, GRADE_BASE/runs.tsv: test_cli runs every step's --help, the stress
# tests steps 04 and 05), the hidden scenes
# and the limits (not on the render threads: a render is the same on any
# number of them). A step whose programs are the same code as a step graded
# before (the solution's, the untouched starter's, another submission's) takes
# that step's results from GRADE_BASE/steps/KEY (docs/grading.md, "How a
# submission is graded").

# code_hash FILE: the SHA-1 of a program's code and data, without its debug
# information and build ID (they name the folder it was built in); a unique
# word when it cannot be read, so it never matches.
# Each program is hashed once per submission (in the folder HASHES).
code_hash() {
  local t h memo=""
  [ -z "${HASHES:-}" ] || memo=$HASHES/$(slug "$1")
  if [ -n "$memo" ] && [ -f "$memo" ]; then cat "$memo"; return; fi
  t=$(mktemp)
  if safe_file "$1" && timeout 60 objcopy --strip-debug --remove-section=.note.gnu.build-id "$1" "$t" 2>/dev/null
  then
    h=$(sha1sum <"$t" | cut -c1-40)
    [ -z "$memo" ] || echo "$h" >"$memo"
  else h="unread-$$-$RANDOM-$(now)"; fi
  rm -f "$t"
  echo "$h"
}

# step_key TREE STEP: what the step's verdicts depend on, hashed.
step_key() {
  local tree=$1 step=$2 b progs=() scene c s mode seed cost rest
  if [ "$step" = stress ]; then progs=(build/tests/stress); else progs=("build/tests/$step" "build/bin/$step"); fi
  grep -qx "$step" "$GRADE_BASE/traces.txt" 2>/dev/null && progs+=(build/bin/trace-diff)
  if [ -f "$GRADE_BASE/runs.tsv" ]; then
    for b in $(awk -F'\t' -v s="$step" '$1 == s { print $2 }' "$GRADE_BASE/runs.tsv"); do
      progs+=("build/bin/$b")
    done
  else
    for b in "$tree"/build/bin/*; do progs+=("build/bin/${b##*/}"); done
  fi
  {
    echo "$GRADE_BASE $SANDBOX_MODE"
    compgen -v | grep '^GRADE_[A-Z_]*\(MIN\|WALL\|SLOWER\|RATIO\|MB\|NPROC\|CPU\)$' | sort |
      while read -r b; do echo "$b=${!b}"; done
    for b in $(printf '%s\n' "${progs[@]}" | sort -u); do echo "$b $(code_hash "$tree/$b")"; done
    if [ -s "$GRADE_PLAN" ]; then
      while IFS=$'\t' read -r c s scene mode seed cost rest; do
        [ "$s" = "$step" ] && echo "$c $(sha1sum <"$scene") $mode $seed $(hidden_wall "$cost") $rest"
      done <"$GRADE_PLAN"
    fi
  } | sha1sum | cut -c1-40
}

# step_copy FROM TO STEP: the step's lines of checks.tsv and pictures.tsv and
# its files in details/, pictures/ and logs/ (all named after the step).
step_copy() {
  local from=$1 to=$2 step=$3 d f
  for d in details pictures logs; do
    mkdir -p "$to/$d"
    for f in "$from/$d/$step".* "$from/$d/${step}"_*; do [ ! -f "$f" ] || cp -p "$f" "$to/$d/"; done
  done
  for f in checks.tsv pictures.tsv; do
    [ -f "$from/$f" ] && awk -v p="$step/" 'index($0, p) == 1' "$from/$f" >>"$to/$f"
  done
  return 0
}

# step_reuse KEY STEP: the results of an earlier step with KEY, if any.
step_reuse() {
  [ -f "$GRADE_BASE/steps/$1/done" ] || return 1
  step_copy "$GRADE_BASE/steps/$1" "$res" "$2"
}

# step_save KEY STEP: keep this step's results under KEY.
step_save() {
  local dir=$GRADE_BASE/steps/$1 tmp
  [ -d "$dir" ] && return 0
  mkdir -p "$GRADE_BASE/steps"
  tmp=$(mktemp -d "$GRADE_BASE/steps/.new.XXXXXX")
  step_copy "$res" "$tmp" "$2"
  touch "$tmp/done"
  mv -T "$tmp" "$dir" 2>/dev/null || rm -rf "$tmp"
}
