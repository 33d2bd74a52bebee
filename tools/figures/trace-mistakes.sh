#!/usr/bin/env bash
# The pictures and trace lines of each step doc's "Seeing the mistake" section
# (make trace-mistakes, on purpose only): for each step, its most common
# mistake is made in a scratch copy of the tree (one line of the solution
# changed with sed), the step is built there, the reference trace of one pixel
# is compared with the mistaken one (tools/figures/traces.sh compare: the first line
# that differs, as make trace-step shows it) and a picture of one quantity
# (--aov) is rendered next to the right one, into docs/img/NN-mistake.*.png.
# Usage: [OUT=DIR] tools/figures/trace-mistakes.sh BUILD [STEP...]   (default: every
# step; make regen runs it through tools/figures/docimg.sh, OUT a scratch folder;
# default docs/img). The scratch tree (BUILD/trace-mistakes) is kept from one
# run to the next: each mistake rebuilds only what it changed.
set -euo pipefail
build=${1:?usage: tools/figures/trace-mistakes.sh BUILD [STEP...]}; shift
. "$(dirname "$0")/../check/scratch.sh"
scratch_top trace-mistakes
scratch=$build/trace-mistakes
img=${OUT:-docs/img}
mkdir -p "$img"
size="--width 320 --height 240 --threads 2 --quiet"

# step | file | sed expression | pixel | what to draw (an --aov, or "" for the picture)
mistakes() {
  cat <<'EOF'
01-film|steps/01-film/main.c|s/bottom = j < film->height \/ 2;/bottom = j >= film->height \/ 2;/|10 10|
02-intersection|common/sphere.c|s/^    return t0;$/    return t1;/|47 150|normal
03-camera|common/camera.c|s/cam->half_w = cam->half_h \* aspect;/cam->half_w = cam->half_h;/|127 100|normal
04-phong|common/phong.c|s/glms_vec3_scale(glms_vec3_mul(m->specular, li), lobe)/glms_vec3_scale(m->specular, lobe)/|171 99|specular
05-shadows|common/ray.h|s/float push = 2.0f \* hit->p_err \* vec_sum_abs(hit->n);/float push = 0.0f;/|155 80|shadow
06-ambient|common/shade.c|s/return glms_vec3_divs(light->power, hit.t \* hit.t);/return light->power;/|277 14|ambient
07-antialiasing|common/antialias.c|s/vec3s lo = glms_vec3_broadcast(1.0f), hi = glms_vec3_zero();/vec3s lo = glms_vec3_zero(), hi = glms_vec3_broadcast(1.0f);/|250 200|samples
08-area-lights|common/area_light.c|s/cos_light \/ ((float)n \* r2)/1.0f \/ ((float)n * r2)/|96 160|diffuse
EOF
}

want=" $* "
mistakes | while IFS='|' read -r step file expr pixel aov; do
  [ "$want" = "  " ] || [[ "$want" == *" $step "* ]] || continue
  echo "== $step: $file: $expr"
  scratch_sync "$top" "$scratch"
  sed -i "$expr" "$scratch/$file"
  if cmp -s "$file" "$scratch/$file"; then echo "$step: the mistake did not apply to $file"; exit 1; fi
  make -s -C "$scratch" -j2 "build/bin/$step" build/bin/trace-diff > /dev/null
  read -r x y <<<"$pixel"
  echo "\$ make trace-step $((10#${step%%-*})) $x $y"
  (cd "$scratch" && tools/figures/traces.sh compare build "$step" "$x" "$y") || true
  name=$img/${step%%-*}-mistake
  if [ -n "$aov" ]; then
    "$scratch/build/bin/$step" $size --aov "$aov" -o "$name.$aov.png" 2>/dev/null
    "$build/bin/$step" $size --aov "$aov" -o "$name.right.$aov.png" 2>/dev/null
  else
    "$scratch/build/bin/$step" --threads 2 --quiet -o "$name.png"
  fi
  scratch_restore "$top" "$scratch" "$file"
done
