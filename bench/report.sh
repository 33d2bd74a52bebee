#!/usr/bin/env bash
# Second half of `make bench` (bench/run.sh): docs/benchmarks.md and its
# plots from the CSV files in docs/bench/. Usage: bench/report.sh SECONDS POVRAY
set -uo pipefail
cd "$(dirname "$0")/.."
D=docs/bench; OUT=docs/benchmarks.md
total=${1:-?}; POV=${2:-}

# table CSV: a Markdown table of a CSV file.
table() {
  awk -F, 'NR == 1 {h = "|"; s = "|"; for (i = 1; i <= NF; i++) {h = h " " $i " |"; s = s "---|"}
    print h; print s; next} {r = "|"; for (i = 1; i <= NF; i++) r = r " " $i " |"; print r}' "$1"
}
# col CSV KEYCOL KEY COL: the value in column COL of the row whose KEYCOL is KEY.
col() { awk -F, -v k="$3" -v kc="$2" -v c="$4" 'NR > 1 && $kc == k {print $c; exit}' "$1"; }
# best_at CSV RENDERER TARGET COL: the least time (column COL) reaching RMSE <= TARGET.
best_at() {
  awk -F, -v r="$2" -v t="$3" -v c="$4" 'NR > 1 && $1 == r && $5 <= t && (b == "" || $c < b) {b = $c; s = $2}
    END {print (b == "" ? "nan" : b) "|" s}' "$1"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {if (a + 0 > 0 && b + 0 > 0) printf "%.1f", a / b; else print "n/a"}'; }
met() { awk -v v="$1" -v t="$2" -v le="${3:-}" 'BEGIN {if (v == "n/a" || v == "nan" || v == "") print "not measured";
  else if ((le == "" && v + 0 >= t) || (le != "" && v + 0 <= t)) print "**met**"; else print "not met"}'; }

plot_error() { # CSV PNG TITLE
  [ -s "$1" ] || return 0
  awk -F, 'NR > 1 && $1 == "ours" && $2 ~ /adaptive=0$/ {split($2, w, " "); print $4, $5 > "/tmp/bench_o_" w[1]}
    NR > 1 && $1 == "ours" && $2 !~ /adaptive=0$/ {print $4, $5 > "/tmp/bench_oa"}
    NR > 1 && $1 == "povray" {print $4, $5 > "/tmp/bench_p"}' "$1"
  local plots="" f
  for f in /tmp/bench_o_*; do
    [ -s "$f" ] && plots+="'$f' u 1:2 w lp t 'ours, ${f#/tmp/bench_o_}', "
  done
  [ -s /tmp/bench_oa ] && plots+="'/tmp/bench_oa' u 1:2 w p pt 7 t 'ours, adaptive', "
  [ -s /tmp/bench_p ] && plots+="'/tmp/bench_p' u 1:2 w p pt 5 t 'POV-Ray 3.7', "
  gnuplot -e "set terminal pngcairo size 800,560; set output '$2'; set logscale xy;
    set xlabel 'wall time per frame, whole process (s)'; set ylabel 'RMSE against own converged image';
    set title '$3'; set grid; set key outside right; plot ${plots%, }" 2>/dev/null
  rm -f /tmp/bench_o_* /tmp/bench_oa /tmp/bench_p
}
plot_error "$D/error-07.csv" "$D/error-07.png" "Step 07 antialiasing, 320x240, 2 threads"
plot_error "$D/error-08.csv" "$D/error-08.png" "Step 08 area light, 320x240, 2 threads"
[ -s "$D/scaling.csv" ] && gnuplot -e "set terminal pngcairo size 720,480; set output '$D/scaling.png';
  set datafile separator ','; set logscale x; set xlabel 'spheres on the plane';
  set ylabel 'seconds per frame (median)'; set title 'Step 05, 800x600, 2 threads'; set grid;
  set key top left; plot '$D/scaling.csv' u 1:2 skip 1 w lp t 'render (BVH)',
  '' u 1:5 skip 1 w lp t 'whole process (parse, build, render, save)'" 2>/dev/null
[ -s "$D/throughput.csv" ] && gnuplot -e "set terminal pngcairo size 720,420; set output '$D/throughput.png';
  set datafile separator ','; set style data histograms; set style fill solid 0.8; set boxwidth 0.8;
  set ylabel 'Mrays/s (median)'; set title 'scenes/spheres.scene, 800x600'; set grid y;
  set xtics rotate by -20; plot '< grep \",1,\" $D/throughput.csv' u 7:xtic(1) t '1 thread',
  '< grep \",2,\" $D/throughput.csv' u 7 t '2 threads'" 2>/dev/null

# Headline figures.
mr05=$(awk -F, '$1 == "05-shadows" && $2 == 2 {print $7}' "$D/throughput.csv")
r05=$(awk -F, '$1 == "05-shadows" && $2 == 2 {print $4}' "$D/throughput.csv")
w05=$(awk -F, '$1 == "05-shadows" && $2 == 2 {print $8}' "$D/throughput.csv")
ptr=$(col "$D/povray.csv" 1 2 2); pw=$(col "$D/povray.csv" 1 2 5)
trace_ratio=$(ratio "$ptr" "$r05"); wall_ratio=$(ratio "$pw" "$w05")
IFS='|' read -r o7 o7s < <(best_at "$D/error-07.csv" ours 1e-3 4)
IFS='|' read -r p7 p7s < <(best_at "$D/error-07.csv" povray 1e-3 4)
IFS='|' read -r o8 o8s < <(best_at "$D/error-08.csv" ours 1e-3 4)
IFS='|' read -r p8 p8s < <(best_at "$D/error-08.csv" povray 1e-3 4)
IFS='|' read -r o7t _ < <(best_at "$D/error-07.csv" ours 1e-3 3)
IFS='|' read -r p7t _ < <(best_at "$D/error-07.csv" povray 1e-3 3)
IFS='|' read -r o8t _ < <(best_at "$D/error-08.csv" ours 1e-3 3)
IFS='|' read -r p8t _ < <(best_at "$D/error-08.csv" povray 1e-3 3)
e7=$(ratio "$p7" "$o7"); e8=$(ratio "$p8" "$o8"); e7t=$(ratio "$p7t" "$o7t"); e8t=$(ratio "$p8t" "$o8t")
s3=$(col "$D/scaling.csv" 1 1000 2); s6=$(col "$D/scaling.csv" 1 1000000 2)
w3=$(col "$D/scaling.csv" 1 1000 5); w6=$(col "$D/scaling.csv" 1 1000000 5)
sc=$(ratio "$s6" "$s3"); scw=$(ratio "$w6" "$w3")

{
cat <<EOF
# Benchmarks

Written by \`make bench\` (bench/run.sh, bench/report.sh) on $(date -u +%Y-%m-%d) in
${total} s, on: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores,
$(gcc --version | head -n1), POV-Ray: ${POV:-not installed}. Every figure is a
median over repeated runs in this one run (min and max in the CSV files);
the machines are shared and noisy, so compare within the run, not across runs.
Raw data: [docs/bench/](bench/). How the fast paths work and what each saves:
[performance.md](performance.md).

## Headline

| target (2 threads, medians) | measured | |
|---|---|---|
| step 05 (hard shadows) traces >= 47 Mrays/s | ${mr05:-n/a} Mrays/s | $(met "${mr05:-n/a}" 47) |
| trace throughput >= 5x POV-Ray's (same scene, trace time) | ${trace_ratio}x | $(met "$trace_ratio" 5) |
| whole process >= 20x faster than POV-Ray's | ${wall_ratio}x | $(met "$wall_ratio" 20) |
| step 07 reaches RMSE 1e-3 >= 5x sooner than POV-Ray's best (wall) | ${e7}x (trace time: ${e7t}x) | $(met "$e7" 5) |
| step 08 reaches RMSE 1e-3 >= 5x sooner than POV-Ray's best (wall) | ${e8}x (trace time: ${e8t}x) | $(met "$e8" 5) |
| 10^6 spheres take <= 3x the time of 10^3 (render) | ${sc}x (whole process: ${scw}x) | $(met "$sc" 3 le) |

Commands: \`build/bin/05-shadows --scene scenes/spheres.scene --threads 2 -o x.png\`
against \`povray -D +W800 +H600 +WT2 Declare=Step=5 bench/spheres.pov\`
(trace time = POV-Ray's "Trace Time" against our summary line's render time;
whole process = wall clock of the command, PNG written by both). At RMSE 1e-3:
step 07 ours \`${o7s:-none}\` in ${o7} s, POV-Ray \`${p7s:-none}\` in ${p7} s;
step 08 ours \`${o8s:-none}\` in ${o8} s, POV-Ray \`${p8s:-none}\` in ${p8} s.

## Throughput: scenes/spheres.scene at 800x600

Each step renders the canonical scene (5 spheres, a plane, a point and a
directional light; from step 05 on with hard shadows; 1 sample per pixel), $(
) \`build/bin/NN-name --scene scenes/spheres.scene --threads T -o x.png\`.
render = the loop's wall time (summary line); wall = the whole process.

$(table "$D/throughput.csv")

![throughput](bench/throughput.png)

POV-Ray 3.7, the same scene (\`bench/spheres.pov\`, Declare=Step=5), PNG out:

EOF
if [ -n "$POV" ]; then table "$D/povray.csv"; else echo "POV-Ray is not installed (\`apt-get install povray\`): this section and the POV-Ray rows below are empty."; fi
cat <<EOF

## Run time against error

320x240, 2 threads. Each renderer against its own converged image: ours
\`--samples 1024 --sampler sobol --adaptive 0\` (step 07) and \`--samples 1
--light-samples 2048 --adaptive 0\` with the same sampler (step 08; one camera
sample so only the light sampling differs; adaptive sampling off, since its
early stops bias a reference), POV-Ray \`+AM2 +R5 +A0.0\` (step 07) and a 33x33 area light
without AA (step 08). RMSE over all channels of the values clamped to [0, 1]
(bench/rmse.c; POV-Ray writes 16-bit linear PNG). Times: trace = render loop
(ours) or "Trace Time" (POV-Ray), wall = whole process, median of
${BENCH_ERR_RUNS:-5} runs. No closed form is used here: the area light's closed
form (a point's irradiance from a parallelogram) is tested in
tests/test_area_light.c, but a whole picture has none.

### Step 07: samplers, sample counts, adaptive on/off

![error 07](bench/error-07.png)

$(table "$D/error-07.csv" 2>/dev/null)

### Step 08: area-light samples, adaptive on/off

![error 08](bench/error-08.png)

$(table "$D/error-08.csv" 2>/dev/null)

## Scaling: spheres on the plane

\`bench/gen_spheres N\` writes N spheres on a jittered grid over the same patch
of floor (radius ~ 1/sqrt(N)), same camera and lights as the canonical scene;
step 05, 800x600, 2 threads, median of 3. The scene files are in build/bench/.

$(table "$D/scaling.csv")

![scaling](bench/scaling.png)

### Plain loop, SIMD blocks or BVH (RT_ACCEL=loop|flat|bvh)

Render time (s, median) of step 05 by layout; the default picks blocks up to
16 spheres and the BVH above (common/accel.h, ACCEL_FLAT_MAX).

$(table "$D/layout.csv")
EOF
} > "$OUT"
echo "bench: wrote $OUT and $D/ (${total} s)"
