#!/usr/bin/env bash
# `make bench`: throughput, run time against error, scaling, and POV-Ray side
# by side, in one run. Writes docs/benchmarks.md, its plots docs/bench/*.png
# and the CSV they are drawn from (docs/bench/*.csv). It reports; it never
# fails on a figure. BENCH_RUNS (default 9) sets the repetitions of timings.
set -uo pipefail
cd "$(dirname "$0")/.."
B=build/bench; D=docs/bench; BIN=build/bin
RUNS=${BENCH_RUNS:-9}; ERUNS=${BENCH_ERR_RUNS:-5}
mkdir -p "$B" "$D"
CFL="-std=c11 -O2 -Icommon $(pkg-config --cflags cglm stb)"
gcc $CFL bench/gen_spheres.c -lm -o "$B/gen_spheres" || exit 1
gcc $CFL bench/rmse.c build/libcommon.a -lpng -lstb -lm -o "$B/rmse" || exit 1
POV=$(command -v povray || true)
have() { [ -x "$BIN/$1" ]; }
log() { echo "bench: $*" >&2; }
t_start=$EPOCHREALTIME

# stats: numbers on stdin -> "median min max".
stats() { sort -g | awk '{v[NR]=$1} END {if (!NR) {print "nan nan nan"; exit}
  m = NR % 2 ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2; printf "%.6g %.6g %.6g\n", m, v[1], v[NR]}'; }

# ours STEP ARGS...: one run -> "render_s mrays wall_s" (summary line + wall clock).
ours() {
  local step=$1; shift
  local t0=$EPOCHREALTIME line
  line=$("$BIN/$step" "$@" 2>/dev/null | tail -n 1)
  local t1=$EPOCHREALTIME
  sed -E 's/.* ([0-9.]+) Mrays in ([0-9.]+) s .*/\2 \1/' <<<"$line" | tr '\n' ' '
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.6f\n", b - a}'
}
# ours_n N STEP ARGS...: N runs -> "render_med min max wall_med min max mrays".
ours_n() {
  local n=$1; shift
  local out; out=$(for _ in $(seq "$n"); do ours "$@"; done)
  echo "$(cut -d' ' -f1 <<<"$out" | stats) $(cut -d' ' -f3 <<<"$out" | stats) $(head -n1 <<<"$out" | cut -d' ' -f2)"
}
# pov ARGS...: one POV-Ray run -> "trace_s wall_s".
pov() {
  local t0=$EPOCHREALTIME tr
  tr=$(cd "$B" && "$POV" -D -V +GS +GR "$@" ../../bench/spheres.pov 2>&1 | tr '\r' '\n' |
       sed -nE 's/.*Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' | tail -n 1)
  local t1=$EPOCHREALTIME
  awk -v tr="${tr:-nan}" -v a="$t0" -v b="$t1" 'BEGIN {printf "%s %.6f\n", tr, b - a}'
}
pov_n() {
  local n=$1; shift
  local out; out=$(for _ in $(seq "$n"); do pov "$@"; done)
  echo "$(cut -d' ' -f1 <<<"$out" | stats) $(cut -d' ' -f2 <<<"$out" | stats)"
}

# ---------------------------------------------------------------- throughput
log "throughput (steps 04-08 on scenes/spheres.scene, 800x600, $RUNS runs)"
echo "step,threads,mrays,render_med,render_min,render_max,mrays_per_s,wall_med,wall_min,wall_max" > "$D/throughput.csv"
for s in 04-phong 05-shadows 06-ambient 07-antialiasing 08-area-lights; do
  have "$s" || continue
  for t in 1 2; do
    read -r rm rlo rhi wm wlo whi mr < <(ours_n "$RUNS" "$s" --scene scenes/spheres.scene \
      --threads "$t" -o "$B/tp.png")
    echo "$s,$t,$mr,$rm,$rlo,$rhi,$(awk -v a="$mr" -v b="$rm" 'BEGIN{printf "%.2f", a/b}'),$wm,$wlo,$whi" >> "$D/throughput.csv"
  done
done
echo "threads,trace_med,trace_min,trace_max,wall_med,wall_min,wall_max" > "$D/povray.csv"
if [ -n "$POV" ]; then
  log "POV-Ray, same scene"
  for t in 1 2; do
    read -r a b c d e f < <(pov_n "$RUNS" +W800 +H600 +WT$t Declare=Step=5 +Opov5.png)
    echo "$t,$a,$b,$c,$d,$e,$f" >> "$D/povray.csv"
  done
fi

# ---------------------------------------------------------------- error
# err_ours CSV STEP REF LABEL ARGS...: time (median of ERUNS) and RMSE vs REF.
err_ours() {
  local csv=$1 step=$2 ref=$3 label=$4; shift 4
  read -r rm _ _ wm _ _ _ < <(ours_n "$ERUNS" "$step" --width 320 --height 240 --threads 2 \
    -o "$B/e.pfm" "$@")
  echo "ours,$label,$rm,$wm,$("$B/rmse" "$B/e.pfm" "$ref")" >> "$csv"
}
err_pov() {
  local csv=$1 ref=$2 label=$3; shift 3
  read -r tm _ _ wm _ _ < <(pov_n "$ERUNS" +W320 +H240 +WT2 +FN16 File_Gamma=1.0 +Oe.png "$@")
  echo "povray,$label,$tm,$wm,$("$B/rmse" "$B/e.png" "$ref")" >> "$csv"
}
EH="renderer,setting,trace_s,wall_s,rmse"
if have 07-antialiasing; then
  log "run time against error, step 07 (320x240)"
  echo "$EH" > "$D/error-07.csv"
  # The converged image without adaptive sampling (step 07's default is on):
  # adaptive pixels stop early, so a reference made with it is biased.
  "$BIN/07-antialiasing" --width 320 --height 240 --threads 2 --quiet --sampler sobol \
    --samples 1024 --adaptive 0 -o "$B/ref07.pfm"
  for smp in grid random jitter sobol; do
    for n in 1 4 16 32 48 64 256; do
      [ "$n" = 256 ] && [ "$smp" != sobol ] && continue
      [ "$n" = 32 ] && [ "$smp" != sobol ] && continue
      for a in 0 0.02 0.05; do
        [ "$a" != 0 ] && [ "$n" -le 4 ] && continue
        [ "$a" = 0.05 ] && [ "$smp" != sobol ] && continue
        err_ours "$D/error-07.csv" 07-antialiasing "$B/ref07.pfm" "$smp n=$n adaptive=$a" \
          --sampler "$smp" --samples "$n" --adaptive "$a"
      done
    done
  done
  if [ -n "$POV" ]; then
    (cd "$B" && "$POV" -D +W320 +H240 +WT2 +FN16 File_Gamma=1.0 Declare=Step=7 \
      +A0.0 +AM2 +R5 +Oref07pov.png ../../bench/spheres.pov >/dev/null 2>&1)
    err_pov "$D/error-07.csv" "$B/ref07pov.png" "no AA" Declare=Step=7 -A
    for am in 1 2; do for r in 2 3 4; do for th in 0.3 0.1 0.03 0.01; do
      [ "$am" = 1 ] && [ "$r" = 4 ] && continue
      err_pov "$D/error-07.csv" "$B/ref07pov.png" "+AM$am +R$r +A$th" Declare=Step=7 \
        +A$th +AM$am +R$r
    done; done; done
  fi
fi
if have 08-area-lights; then
  log "run time against error, step 08 (320x240, 1 camera sample)"
  echo "$EH" > "$D/error-08.csv"
  for smp in grid jitter sobol; do
    # Reference without adaptive light sampling (on by default): unbiased.
    "$BIN/08-area-lights" --width 320 --height 240 --threads 2 --quiet --sampler "$smp" \
      --samples 1 --light-samples 2048 --adaptive 0 -o "$B/ref08-$smp.pfm"
    for n in 1 4 16 64 100 121 144 256; do
      { [ "$n" = 100 ] || [ "$n" = 121 ] || [ "$n" = 144 ]; } && [ "$smp" != grid ] && continue
      for a in 0 0.02; do
        [ "$a" != 0 ] && [ "$n" -le 4 ] && continue
        err_ours "$D/error-08.csv" 08-area-lights "$B/ref08-$smp.pfm" \
          "$smp light-samples=$n adaptive=$a" --sampler "$smp" --samples 1 \
          --light-samples "$n" --adaptive "$a"
      done
    done
  done
  if [ -n "$POV" ]; then
    (cd "$B" && "$POV" -D +W320 +H240 +WT2 +FN16 File_Gamma=1.0 -A Declare=Step=8 \
      Declare=AreaN=33 Declare=AreaAdaptive=0 +Oref08pov.png ../../bench/spheres.pov >/dev/null 2>&1)
    for n in 2 3 5 9 17; do for ad in 0 1 2; do
      [ "$ad" -gt 0 ] && [ "$n" -lt 5 ] && continue
      err_pov "$D/error-08.csv" "$B/ref08pov.png" "area_light ${n}x$n adaptive $ad" -A \
        Declare=Step=8 Declare=AreaN=$n Declare=AreaAdaptive=$ad
    done; done
  fi
fi

# ---------------------------------------------------------------- scaling
if have 05-shadows; then
  log "scaling (step 05, 2 threads, 10 .. 10^6 spheres)"
  echo "spheres,render_med,render_min,render_max,wall_med,wall_min,wall_max" > "$D/scaling.csv"
  for n in 10 100 1000 10000 100000 1000000; do
    [ -s "$B/spheres-$n.scene" ] || "$B/gen_spheres" "$n" > "$B/spheres-$n.scene"
    read -r rm rlo rhi wm wlo whi _ < <(ours_n 3 05-shadows --scene "$B/spheres-$n.scene" \
      --threads 2 -o "$B/s.pfm")
    echo "$n,$rm,$rlo,$rhi,$wm,$wlo,$whi" >> "$D/scaling.csv"
  done
  log "layouts: plain loop, SIMD blocks, BVH (step 05, 2 threads)"
  echo "spheres,loop,flat,bvh" > "$D/layout.csv"
  for n in 5 10 20 50 100 1000; do
    sc="$B/spheres-$n.scene"; [ "$n" = 5 ] && sc=scenes/spheres.scene
    [ -s "$sc" ] || "$B/gen_spheres" "$n" > "$sc"
    row=$n
    for l in loop flat bvh; do
      export RT_ACCEL=$l
      row+=,$(ours_n "$RUNS" 05-shadows --scene "$sc" --threads 2 -o "$B/s.pfm" | cut -d' ' -f1)
    done
    unset RT_ACCEL
    echo "$row" >> "$D/layout.csv"
  done
fi

t_total=$(awk -v a="$t_start" -v b="$EPOCHREALTIME" 'BEGIN {printf "%.0f", b - a}')
bench/report.sh "$t_total" "$POV"
