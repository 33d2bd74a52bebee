#!/usr/bin/env bash
# `make bench`: throughput, run time against error at 800x600, thread scaling
# and POV-Ray side by side, in one run. Writes docs/benchmarks.md, its plots
# docs/bench/*.png and the CSV files they are drawn from (docs/bench/*.csv).
# It reports; it never fails on a figure. Environment: BENCH_RUNS (default 9)
# repetitions of the throughput timings, BENCH_PAIRS (21) pairs of the two
# rows timed in turn (step 05 against POV-Ray, 10^3 against 10^6 spheres:
# their medians move least with more pairs), BENCH_ERR_RUNS (3) of the error
# sweeps, THREADS_ALL (default: nproc) the "all cores" thread count,
# BENCH_PARTS (default: all of them) the parts to run, among: throughput
# vs nopack step05 error07 error08 threads scaling report (threads reads the
# error CSVs; report reads them all), BENCH_PREBUILT=1 to use the programs
# already in build/ (build/bin, build/bench-notrace, build/bench/gen_spheres
# and rmse) without compiling anything: a machine that runs but cannot build;
# BENCH_VS=DIR another build's bin/ folder, timed against this one (part vs).
set -uo pipefail
cd "$(dirname "$0")/.."
B=build/bench; D=docs/bench; BIN=build/bin; REF=$B/refs
RUNS=${BENCH_RUNS:-9}; PAIRS=${BENCH_PAIRS:-21}; ERUNS=${BENCH_ERR_RUNS:-3}; ALL=${THREADS_ALL:-$(nproc)}
PARTS=" ${BENCH_PARTS:-throughput vs nopack step05 error07 error08 threads scaling report} "
PRESENT_STEPS=$(cd "$BIN" 2>/dev/null && ls -d [0-9][0-9]-* 2>/dev/null)
PREBUILT=${BENCH_PREBUILT:-}
part() { [[ "$PARTS" == *" $1 "* ]]; }
W=800; H=600
mkdir -p "$B" "$D" "$REF"
# The build measured: the Makefile's flags (CC, CFLAGS, LDFLAGS, LDLIBS, and
# BUILD_KIND: portable, or native with make NATIVE=1), printed and reported.
eval "$(make --no-print-directory -s print-flags)" || [ -n "$PREBUILT" ] || exit 1
export BENCH_BUILD="$BUILD_KIND"
echo "bench: measuring the $BUILD_KIND build: $CC $CFLAGS" >&2
if [ -z "$PREBUILT" ]; then
  $CC -std=c11 -O2 bench/gen_spheres.c -lm -o "$B/gen_spheres" || exit 1
  # shellcheck disable=SC2086
  $CC $CFLAGS $LDFLAGS bench/rmse.c build/libcommon.a $LDLIBS -o "$B/rmse" || exit 1
fi
POV=$(command -v povray || true)
POV_SCENE=bench/spheres.pov
have() { [ -x "$BIN/$1" ]; }
log() { echo "bench: $*" >&2; }
t_start=$EPOCHREALTIME
load_start=$(cut -d' ' -f1 /proc/loadavg)
# The thread counts measured: 2, and all cores when that is another count.
TLIST="2"; [ "$ALL" != 2 ] && TLIST="2 $ALL"

# stats: numbers on stdin -> "median min max".
stats() { sort -g | awk '{v[NR]=$1} END {if (!NR) {print "nan nan nan"; exit}
  m = NR % 2 ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2; printf "%.6g %.6g %.6g\n", m, v[1], v[NR]}'; }

# ours STEP ARGS...: one run -> "trace_s mrays wall_s" (summary line + wall clock).
ours() {
  local step=$1; shift
  local t0=$EPOCHREALTIME line
  line=$("$BIN/$step" "$@" 2>/dev/null | tail -n 1)
  local t1=$EPOCHREALTIME
  sed -E 's/.* ([0-9.]+) Mrays in ([0-9.]+) s .*/\2 \1/' <<<"$line" | tr '\n' ' '
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.6f\n", b - a}'
}
# ours_n N STEP ARGS...: N runs -> "trace_med min max wall_med min max mrays".
ours_n() {
  local n=$1; shift
  local out; out=$(for _ in $(seq "$n"); do ours "$@"; done)
  echo "$(cut -d' ' -f1 <<<"$out" | stats) $(cut -d' ' -f3 <<<"$out" | stats) $(head -n1 <<<"$out" | cut -d' ' -f2)"
}
# in_turn OTHER STEP ARGS...: $RUNS pairs, this build's run of STEP then the
# one in OTHER (another bin/ folder), a line each: "trace mrays wall" twice.
in_turn() {
  local other=$1; shift
  for _ in $(seq "$RUNS"); do echo "$(ours "$@") $(BIN=$other ours "$@")"; done
}
# pair_median PAIRS EXPR: the median of the awk expression EXPR ($3, $6 / $3)
# over the lines of PAIRS.
pair_median() { awk "{print $2}" <<<"$1" | stats | cut -d' ' -f1; }
# pov ARGS...: one POV-Ray run (PNG out) -> "trace_s wall_s".
pov() {
  local t0=$EPOCHREALTIME tr
  tr=$(cd "$B" && "$POV" -D -V +GS +GR "$@" "../../$POV_SCENE" 2>&1 | tr '\r' '\n' |
       sed -nE 's/.*Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' | tail -n 1)
  local t1=$EPOCHREALTIME
  awk -v tr="${tr:-nan}" -v a="$t0" -v b="$t1" 'BEGIN {printf "%s %.6f\n", tr, b - a}'
}
pov_n() {
  local n=$1; shift
  local out; out=$(for _ in $(seq "$n"); do pov "$@"; done)
  echo "$(cut -d' ' -f1 <<<"$out" | stats) $(cut -d' ' -f2 <<<"$out" | stats)"
}
# Converged references are kept in build/bench/refs/, named by a checksum of
# the program, the scene and the options: a later run reuses them.
key() { cat "$@" 2>/dev/null | md5sum | cut -c1-16; }
ref_ours() { # STEP ARGS... -> prints the reference's path
  local step=$1; shift
  local f; f="$REF/$step-$(key "$BIN/$step" <(echo "$@")).pfm"
  [ -s "$f" ] || { log "reference: $step $*"; "$BIN/$step" --quiet "$@" -o "$f.tmp.pfm" &&
                   mv "$f.tmp.pfm" "$f"; }
  echo "$f"
}
ref_pov() { # ARGS... -> prints the reference's path (16-bit linear PNG)
  local f; f="$REF/pov-$(key "$POV" "$POV_SCENE" <(echo "$@")).png"
  [ -s "$f" ] || { log "reference: povray $*"; (cd "$B" && "$POV" -D -V +GS +GR "$@" \
      +O"refs/tmp.png" "../../$POV_SCENE" >/dev/null 2>&1) && mv "$REF/tmp.png" "$f"; }
  echo "$f"
}

# ---------------------------------------------------------------- throughput
if part throughput; then
log "throughput (steps 04-08 on scenes/spheres.scene, ${W}x$H, $RUNS runs)"
echo "step,threads,mrays,trace_med,trace_min,trace_max,mrays_per_s,wall_med,wall_min,wall_max" > "$D/throughput.csv"
for s in 04-phong 05-shadows 06-ambient 07-antialiasing 08-area-lights; do
  have "$s" || continue
  for t in 1 $TLIST; do
    read -r rm rlo rhi wm wlo whi mr < <(ours_n "$RUNS" "$s" --scene scenes/spheres.scene \
      --threads "$t" -o "$B/tp.png")
    echo "$s,$t,$mr,$rm,$rlo,$rhi,$(awk -v a="$mr" -v b="$rm" 'BEGIN{printf "%.2f", a/b}'),$wm,$wlo,$whi" >> "$D/throughput.csv"
  done
done
echo "threads,trace_med,trace_min,trace_max,wall_med,wall_min,wall_max" > "$D/povray.csv"
if [ -n "$POV" ]; then
  log "POV-Ray, same scene"
  for t in 1 $TLIST; do
    read -r a b c d e f < <(pov_n "$RUNS" +W$W +H$H +WT$t Declare=Step=5 +Opov5.png)
    echo "$t,$a,$b,$c,$d,$e,$f" >> "$D/povray.csv"
  done
fi
fi

# Against another build (BENCH_VS=DIR, the bin/ folder of another tree's
# build, e.g. an older commit's): steps 04-08's default renders by this build
# and by that one, in turn, 2 threads, the whole process; medians, and the
# median and range of the pairs' ratios (this / other; below 1, this one is
# faster).
if part vs; then
echo "step,pairs,wall_this,wall_other,ratio_med,ratio_min,ratio_max" > "$D/vs.csv"
if [ -n "${BENCH_VS:-}" ] && [ -x "$BENCH_VS/05-shadows" ]; then
  log "against $BENCH_VS: steps 04-08, this build and that one in turn ($RUNS pairs)"
  for s in 04-phong 05-shadows 06-ambient 07-antialiasing 08-area-lights; do
    { have "$s" && [ -x "$BENCH_VS/$s" ]; } || continue
    pairs=$(in_turn "$BENCH_VS" "$s" --threads 2 -o "$B/vs.png")
    r=$(awk '{print $3 / $6}' <<<"$pairs" | stats | tr ' ' ,)
    echo "$s,$RUNS,$(pair_median "$pairs" '$3'),$(pair_median "$pairs" '$6'),$r" >> "$D/vs.csv"
  done
  # Which build: the folder, and the commit it was built from when it is
  # inside a git work tree.
  vs_commit=$(git -C "$BENCH_VS" rev-parse --short HEAD 2>/dev/null)
  echo "$BENCH_VS${vs_commit:+ (commit $vs_commit)}" > "$D/vs.txt"
else
  log "against another build: BENCH_VS not set (or no programs in it): skipped"
  : > "$D/vs.txt"
fi
fi

# Without the speed pack (docs/performance.md): every step's default render
# built with FAST=0 (in build/bench-nofast), both builds run in turn, whole
# process, medians and the median of the pairs' ratios (FAST=0 / default).
NF=build/bench-nofast
if part nopack; then
echo "step,pairs,wall_default,wall_fast0,wall_ratio" > "$D/pack-off.csv"
steps_nf=$(for s in $PRESENT_STEPS; do echo "$NF/bin/$s"; done)
if { [ -n "$PREBUILT" ] && [ -x "$NF/bin/05-shadows" ]; } ||
   make --no-print-directory BUILD=$NF FAST=0 $steps_nf >"$B/nofast.log" 2>&1; then
  log "speed pack off: every step's default render, FAST=1 and FAST=0 in turn ($RUNS pairs)"
  for s in $PRESENT_STEPS; do
    pairs=$(in_turn "$NF/bin" "$s" -o "$B/pk.png")
    echo "$s,$RUNS,$(pair_median "$pairs" '$3'),$(pair_median "$pairs" '$6'),$(pair_median "$pairs" '$6 / $3')" \
      >> "$D/pack-off.csv"
  done
else
  log "speed pack off: the FAST=0 build failed ($B/nofast.log)"
fi
fi

# Step 05's one-sample frame against POV-Ray's, the two run in turn (ours,
# POV-Ray, ours, ...) so that a change of the machine's load hits both: the
# headline's figures.
if part step05; then
echo "renderer,threads,trace_med,wall_med" > "$D/step05.csv"
if [ -n "$POV" ] && have 05-shadows; then
  log "step 05 and POV-Ray in turn ($PAIRS pairs)"
  for t in $TLIST; do
    o=""; p=""
    for _ in $(seq "$PAIRS"); do
      o+="$(ours 05-shadows --scene scenes/spheres.scene --threads "$t" -o "$B/tp.png")"$'\n'
      p+="$(pov +W$W +H$H +WT"$t" Declare=Step=5 +Opov5.png)"$'\n'
    done
    med() { grep -v '^$' | stats | cut -d' ' -f1; }
    echo "ours,$t,$(cut -d' ' -f1 <<<"$o" | med),$(cut -d' ' -f3 <<<"$o" | med)" >> "$D/step05.csv"
    echo "povray,$t,$(cut -d' ' -f1 <<<"$p" | med),$(cut -d' ' -f2 <<<"$p" | med)" >> "$D/step05.csv"
  done
fi
fi

# ---------------------------------------------------------------- error
# CSV rows: renderer,setting,threads,trace_s,wall_s,rmse. RMSE over all
# channels of the values clamped to [0, 1], against the renderer's own
# converged reference, rendered without adaptive sampling.
EH="renderer,setting,threads,trace_s,wall_s,rmse"
err_ours() { # CSV STEP REF LABEL THREADS ARGS...
  local csv=$1 step=$2 ref=$3 label=$4 t=$5; shift 5
  read -r rm _ _ wm _ _ _ < <(ours_n "$ERUNS" "$step" --width $W --height $H --threads "$t" \
    -o "$B/e.pfm" "$@")
  echo "ours,$label,$t,$rm,$wm,$("$B/rmse" "$B/e.pfm" "$ref")" >> "$csv"
}
err_pov() { # CSV "REF..." LABEL THREADS ARGS...
  local csv=$1 ref=$2 label=$3 t=$4; shift 4
  read -r tm _ _ wm _ _ < <(pov_n "$ERUNS" +W$W +H$H +WT$t +FN16 File_Gamma=1.0 +Oe.png "$@")
  echo "povray,$label,$t,$tm,$wm,$("$B/rmse" "$B/e.png" $ref)" >> "$csv"
}
if part error07 && have 07-antialiasing; then
  log "run time against error, step 07 (${W}x$H)"
  echo "$EH" > "$D/error-07.csv"
  r07=$(ref_ours 07-antialiasing --width $W --height $H --threads "$ALL" --samples 512 \
        --sampler sobol --adaptive 0 --seed 4242)
  # POV-Ray's reference one level finer than its finest run (+R6 over +R5),
  # so that no run is measured against its own lattice.
  [ -n "$POV" ] && p07=$(ref_pov +W$W +H$H +WT"$ALL" +FN16 File_Gamma=1.0 Declare=Step=7 \
                         +AM2 +R6 +A0.0)
  for t in $TLIST; do
    for n in 16 64; do
      err_ours "$D/error-07.csv" 07-antialiasing "$r07" "sobol n=$n" "$t" --sampler sobol \
        --samples "$n" --adaptive 0
    done
    for set in "16 0.05" "64 0.1" "64 0.05" "256 0.1" "256 0.05" "256 0.02" "1024 0.05"; do
      read -r n a <<<"$set"
      err_ours "$D/error-07.csv" 07-antialiasing "$r07" "adaptive n=$n T=$a" "$t" \
        --samples "$n" --adaptive "$a"
    done
    [ -n "$POV" ] || continue
    for set in "3 0.1" "4 0.1" "4 0.03" "5 0.1" "5 0.03" "5 0.01"; do
      read -r r th <<<"$set"
      err_pov "$D/error-07.csv" "$p07" "+AM2 +R$r +A$th" "$t" Declare=Step=7 +AM2 +R$r +A$th
    done
  done
fi
# povargs08 LABEL: POV-Ray's options for "area_light NxN[ adaptive A][ jitter]".
povargs08() {
  local x=${1#area_light } ad=-1; local n=${x%%x*}
  [[ "$x" == *adaptive* ]] && { ad=${x#*adaptive }; ad=${ad%% *}; }
  echo "-A Declare=Step=8 Declare=AreaN=$n Declare=AreaAdaptive=$ad$([[ "$x" == *jitter* ]] &&
    echo " Declare=AreaJitter=1")"
}
if part error08 && have 08-area-lights; then
  log "run time against error, step 08 (${W}x$H, 1 camera sample)"
  echo "$EH" > "$D/error-08.csv"
  # One camera sample, so that only the light's sampling differs from the
  # reference: grid puts it at the pixel centre, Sobol at the pixel's first
  # point (the same in the reference: same seed).
  for smp in grid sobol; do
    r08=$(ref_ours 08-area-lights --width $W --height $H --threads "$ALL" --samples 1 \
          --sampler $smp --light-samples 4096 --adaptive 0)
    for t in $TLIST; do
      for n in 64 144 256 400; do
        [ $smp = sobol ] && { [ "$n" = 144 ] || [ "$n" = 400 ]; } && continue
        err_ours "$D/error-08.csv" 08-area-lights "$r08" "$smp light-samples=$n" "$t" \
          --samples 1 --sampler $smp --light-samples "$n" --adaptive 0
      done
    done
  done
  if [ -n "$POV" ]; then
    # POV-Ray's reference: the mean of two renders with a jittered 32 x 32
    # area light (a random place in each of the 1024 cells: unbiased; its
    # regular grids put samples on the light's edges with equal weights,
    # biased by O(1/n)).
    p08a=$(ref_pov +W$W +H$H +WT"$ALL" +FN16 File_Gamma=1.0 -A Declare=Step=8 Declare=AreaN=32 \
           Declare=AreaAdaptive=-1 Declare=AreaJitter=1 Declare=Ref=1)
    p08b=$(ref_pov +W$W +H$H +WT"$ALL" +FN16 File_Gamma=1.0 -A Declare=Step=8 Declare=AreaN=32 \
           Declare=AreaAdaptive=-1 Declare=AreaJitter=1 Declare=Ref=2)
    for t in $TLIST; do
      for set in "9 -1 jitter" "17 -1 jitter" "24 -1 jitter" "17 2 -" "33 2 -"; do
        read -r n ad jit <<<"$set"
        label="area_light ${n}x$n$([ "$ad" = -1 ] || echo " adaptive $ad")$([ "$jit" = - ] || echo " jitter")"
        err_pov "$D/error-08.csv" "$p08a $p08b" "$label" "$t" $(povargs08 "$label")
      done
    done
  fi
fi

# ---------------------------------------------------------------- threads
# The settings that reach RMSE 5e-4 soonest (trace time, 2 threads), and the
# one-sample frame of step 05, at 1, 2 and all threads, both renderers.
best() { # CSV RENDERER -> the setting with the least trace time at RMSE <= 5e-4,
  # or the one with the lowest error when none got there
  awk -F, -v r="$2" 'NR > 1 && $1 == r && $3 == 2 {
      if ($6 <= 5e-4 && (b == "" || $4 < b)) {b = $4; s = $2}
      if (m == "" || $6 < m) {m = $6; ms = $2}}
    END {print (s != "" ? s : ms)}' "$1"
}
args07() { case "$1" in "sobol n="*) echo "--sampler sobol --samples ${1#sobol n=} --adaptive 0";;
  "adaptive n="*) local x=${1#adaptive n=}; echo "--samples ${x% T=*} --adaptive ${x#* T=}";; esac; }
args08() { echo "--samples 1 --sampler ${1% light-samples=*} --light-samples ${1#*light-samples=} --adaptive 0"; }
part threads && log "threads: 1 $TLIST" &&
  echo "picture,renderer,setting,threads,trace_med,wall_med" > "$D/threads.csv"
thread_row() { # PICTURE RENDERER SETTING THREADS -> one row
  local pic=$1 who=$2 set=$3 t=$4 a b
  # One run of a setting that took more than 5 s in the error sweep.
  local ERUNS=$ERUNS slow
  slow=$(awk -F, -v r="$who" -v s="$set" '$1 == r && $2 == s && $4 > 5 {print 1; exit}' \
         "$D/error-${pic%% *}.csv" 2>/dev/null)
  [ -n "$slow" ] && ERUNS=1
  if [ "$who" = ours ]; then
    case "$pic" in
      05*) read -r a _ _ b _ _ _ < <(ours_n "$ERUNS" 05-shadows --scene scenes/spheres.scene \
             --threads "$t" -o "$B/th.png");;
      07*) read -r a _ _ b _ _ _ < <(ours_n "$ERUNS" 07-antialiasing --width $W --height $H \
             --threads "$t" $(args07 "$set") -o "$B/th.png");;
      08*) read -r a _ _ b _ _ _ < <(ours_n "$ERUNS" 08-area-lights --width $W --height $H \
             --threads "$t" $(args08 "$set") -o "$B/th.png");;
    esac
  else
    case "$pic" in
      05*) read -r a _ _ b _ _ < <(pov_n "$ERUNS" +W$W +H$H +WT"$t" Declare=Step=5 +Oth.png);;
      07*) read -r a _ _ b _ _ < <(pov_n "$ERUNS" +W$W +H$H +WT"$t" +FN16 File_Gamma=1.0 \
             Declare=Step=7 ${set} +Oth.png);;
      08*) read -r a _ _ b _ _ < <(pov_n "$ERUNS" +W$W +H$H +WT"$t" +FN16 File_Gamma=1.0 \
             $(povargs08 "$set") +Oth.png);;
    esac
  fi
  echo "$pic,$who,$set,$t,$a,$b" >> "$D/threads.csv"
}
if part threads; then
b07o=$(best "$D/error-07.csv" ours 2>/dev/null); b08o=$(best "$D/error-08.csv" ours 2>/dev/null)
b07p=$(best "$D/error-07.csv" povray 2>/dev/null); b08p=$(best "$D/error-08.csv" povray 2>/dev/null)
for t in 1 $TLIST; do
  thread_row "05 one sample" ours "1 sample" "$t"
  [ -n "$b07o" ] && thread_row "07 best setting" ours "$b07o" "$t"
  [ -n "$b08o" ] && thread_row "08 best setting" ours "$b08o" "$t"
  [ -n "$POV" ] || continue
  thread_row "05 one sample" povray "-A" "$t"
  [ -n "$b07p" ] && thread_row "07 best setting" povray "$b07p" "$t"
  [ -n "$b08p" ] && thread_row "08 best setting" povray "$b08p" "$t"
done
fi

# ---------------------------------------------------------------- spheres
if part scaling && have 05-shadows; then
  log "scaling (step 05, 2 threads, 10 .. 10^6 spheres)"
  echo "spheres,trace_med,trace_min,trace_max,wall_med,wall_min,wall_max" > "$D/scaling.csv"
  for n in 10 100 1000 10000 100000 1000000; do
    [ -s "$B/spheres-$n.scene" ] || "$B/gen_spheres" "$n" > "$B/spheres-$n.scene"
    read -r rm rlo rhi wm wlo whi _ < <(ours_n 3 05-shadows --scene "$B/spheres-$n.scene" \
      --threads 2 -o "$B/s.pfm")
    echo "$n,$rm,$rlo,$rhi,$wm,$wlo,$whi" >> "$D/scaling.csv"
  done
  # The ratio from pairs run in turn (10^3 then 10^6), so that a machine
  # whose speed drifts during the run moves both processes alike: medians of
  # separate runs taken one after the other drift apart.
  log "10^6 against 10^3 spheres, whole process, $PAIRS pairs in turn"
  echo "pair,wall_1000,wall_1000000,ratio" > "$D/ratio6.csv"
  for k in $(seq "$PAIRS"); do
    read -r _ _ w3 < <(ours 05-shadows --scene "$B/spheres-1000.scene" --threads 2 -o "$B/s.pfm")
    read -r _ _ w6 < <(ours 05-shadows --scene "$B/spheres-1000000.scene" --threads 2 -o "$B/s.pfm")
    awk -v k="$k" -v a="$w3" -v b="$w6" 'BEGIN {printf "%d,%s,%s,%.4f\n", k, a, b, b / a}' >> "$D/ratio6.csv"
  done
  log "layouts: plain loop, one leaf, BVH (step 05, 2 threads)"
  echo "spheres,loop,flat,bvh" > "$D/layout.csv"
  for n in 5 20 100 1000; do
    sc="$B/spheres-$n.scene"; [ "$n" = 5 ] && sc=scenes/spheres.scene
    [ -s "$sc" ] || "$B/gen_spheres" "$n" > "$sc"
    row=$n
    for l in loop flat bvh; do
      row+=,$(RT_ACCEL=$l ours_n 3 05-shadows --scene "$sc" --threads 2 -o "$B/s.pfm" | cut -d' ' -f1)
    done
    echo "$row" >> "$D/layout.csv"
  done
fi

t_total=$(awk -v a="$t_start" -v b="$EPOCHREALTIME" 'BEGIN {printf "%.0f", b - a}')
if part report; then # a run of some parts only ends without the report, and without failing
  bench/report.sh "$t_total" "$POV" "$ALL" "$load_start $(cut -d' ' -f1 /proc/loadavg)"
fi
