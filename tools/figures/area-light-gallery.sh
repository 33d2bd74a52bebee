#!/usr/bin/env bash
# The pictures of docs/08-area-lights.md: the step's default scene right, with
# too few or badly placed light samples, and with the typical mistakes (each
# made by a one-line change to a copy of common/area_light.c or sampler.c,
# built in
# build/gallery/). Usage: [OUT=DIR] tools/figures/area-light-gallery.sh (after make
# build; make regen runs it through tools/figures/docimg.sh, OUT a scratch folder;
# default docs/img): the pictures go to OUT/08-area-lights/.
set -euo pipefail
out=${OUT:-docs/img}/08-area-lights
bin=build/bin/08-area-lights
tmp=build/gallery
mkdir -p "$out" "$tmp"
size=(--width 320 --height 240 --threads 2 --quiet)
eval "$(make --no-print-directory -s print-flags)" # CC, CFLAGS, LDFLAGS, LDLIBS

$bin "${size[@]}" -o $out/default.png
$bin "${size[@]}" --light-samples 1 -o $out/samples-1.png
$bin "${size[@]}" --light-samples 4 -o $out/samples-4.png
$bin "${size[@]}" --light-samples 64 -o $out/samples-64.png
# One camera sample so the light pattern alone shows.
$bin "${size[@]}" --samples 1 --sampler grid -o $out/grid-same-pattern.png
$bin "${size[@]}" --samples 1 --sampler random -o $out/random-unstratified.png
$bin "${size[@]}" --samples 1 --sampler jitter -o $out/jitter-stratified.png

# mistake NAME FILE SED-EXPRESSION [SCENE]: build the step with one line of
# common/FILE changed.
mistake() {
  local name=$1 file=$2 expr=$3 scene=${4:-}
  mkdir -p $tmp/$name
  cp steps/08-area-lights/main.c common/$file $tmp/$name/
  sed -i "$expr" $tmp/$name/$file
  cmp -s common/$file $tmp/$name/$file && { echo "gallery: '$name' changed nothing" >&2; exit 1; }
  # The Makefile's flags: cglm aligns its types (and so Scene) by -march.
  # The changed file comes before libcommon.a, which then adds only what
  # it lacks.
  # shellcheck disable=SC2086
  $CC $CFLAGS $LDFLAGS -Wno-error -I$tmp/$name -Ibuild/gen/08-area-lights \
    -include step_manifest.h $tmp/$name/main.c $tmp/$name/$file \
    build/obj/gen/08-area-lights-scene.o build/libcommon.a $LDLIBS -o $tmp/$name/bin
  $tmp/$name/bin "${size[@]}" ${scene:+--scene $scene} -o $out/$name.png
}
# Same pattern everywhere: the light samples keyed by the seed only, not by
# the hit point.
mistake same-pattern-every-pixel sampler.c 's/b\[0\] ^ (b\[2\] \* 0x85ebca77u), b\[1\]/0u, 0u/'
mistake no-cos-theta-light area_light.c 's|cos_light / ((float)n \* r2)|1.0f / ((float)n * r2)|'
# The light turned to face the sky: right, the floor gets nothing from it and
# the camera sees its black back; two-sided, the floor is lit anyway.
sed 's/edge1 2 0 0 edge2 0 0.3 1.2/edge1 0 0.3 1.2 edge2 2 0 0/' scenes/area-lights.scene > $tmp/facing-up.scene
$bin "${size[@]}" --scene $tmp/facing-up.scene -o $out/facing-up.png
mistake two-sided-light area_light.c 's|float cos_light = -glms_vec3_dot(\*l, light->quad.normal);|float cos_light = fabsf(glms_vec3_dot(*l, light->quad.normal));|' $tmp/facing-up.scene
echo "gallery: wrote $out/"
