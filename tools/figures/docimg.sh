#!/usr/bin/env bash
# The docs' pictures, docs/img/: every generator below renders its pictures
# into a scratch folder (OUT), and each is compared with the kept one pixel
# by pixel, like the reference images (tools/figures/images.sh); the
# pictures of shadow acne within a tolerance (KNIFE_EDGE below).
# Usage: tools/figures/docimg.sh write|check BUILD
#   write  (make regen) rewrites a picture only when some pixel differs, through
#          the one writer of kept pictures (tools/loop/imgcmp.c --put): "regen: wrote
#          FILE (why)"; with REGEN_DIR set, REGEN_DIR/docimg.sources gets one
#          "FILE<TAB>SCENE" line per picture (the scene it renders)
#   check  (make check-docimg) fails when write would write
# A picture under docs/img/ that no generator makes is named (HAND_MADE lists
# those made by hand on purpose, with where their commands are).
set -uo pipefail
mode=${1:-} build=${2:-}
[ "$mode" = write ] || [ "$mode" = check ] && [ -n "$build" ] ||
  { echo "usage: tools/figures/docimg.sh write|check BUILD" >&2; exit 2; }
here=$(dirname "$0")

# The generators: NAME | command (run with OUT=the scratch folder). Each
# writes its pictures under OUT with their paths under docs/img/.
GENERATORS="mistakes|$here/mistakes.sh $build/bin
aa-mistakes|$here/aa-mistakes.sh
area-light-gallery|$here/area-light-gallery.sh
trace-mistakes|$here/trace-mistakes.sh $build
accuracy|$here/accuracy.sh $build"
# Pictures made by hand on purpose, each with where its commands are: none.
HAND_MADE=""
# Pictures of shadow acne: each acne pixel falls lit or dark on the last bit
# of its hit point, so another compiler or CPU (an ulp apart anywhere) draws
# the acne elsewhere, pixels 255 codes apart. They are compared by
# imgcmp --edge: at most 12 % of the pixels differ and every 16 x 16 block's
# mean is within 40 codes. Measured against a build with fused multiply-add
# (-ffp-contract=fast -march=x86-64-v3): 1.3 to 5.3 % of the pixels, block
# means up to 32.3 codes; the same pictures without their acne (the step's
# right answer): 60.7 to 128 codes. Each has a right-answer twin checked
# exactly (05-right, 05-right-huge, accuracy-robust-large), which shows a
# change of the scene or of the shading.
KNIFE_EDGE="05-no-offset.png 05-epsilon-huge.png accuracy-epsilon-large.png"
EDGE_TOL=16,40,0.12
edge() { case " $KNIFE_EDGE " in *" $1 "*) echo "--edge $EDGE_TOL" ;; esac; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/docimg.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/img" "$tmp/log"
while IFS='|' read -r name cmd; do
  # shellcheck disable=SC2086 # the command and its arguments
  if ! OUT=$tmp/img $cmd > "$tmp/log/$name" 2>&1; then
    tail -n 20 "$tmp/log/$name" >&2
    echo "docimg: $name ($cmd) failed" >&2; exit 1
  fi
done <<<"$GENERATORS"

# scene_of REL: the scene a picture renders: the --scene of the command line
# that wrote it, when a generator printed one, else its step's default scene.
scene_of() {
  local rel=$1 line step
  line=$(grep -h -- "-o $tmp/img/$rel\$" "$tmp/log"/* 2>/dev/null | head -n 1)
  if [[ $line =~ --scene\ ([^ ]+) ]]; then echo "${BASH_REMATCH[1]}"; return; fi
  step=$(cd steps && ls -d "${rel:0:2}"-* 2>/dev/null | head -n 1)
  [ -n "$step" ] && "$here/../build/manifest.sh" get "$step" SCENE
}

stale=0
[ -n "${REGEN_DIR:-}" ] && : > "$REGEN_DIR/docimg.sources"
while IFS= read -r new; do
  rel=${new#"$tmp/img/"}
  kept=docs/img/$rel
  [ -n "${REGEN_DIR:-}" ] && printf '%s\t%s\n' "$kept" "$(scene_of "$rel")" >> "$REGEN_DIR/docimg.sources"
  if [ "$mode" = write ]; then
    mkdir -p "$(dirname "$kept")"
    # shellcheck disable=SC2046 # the tolerance's option and value
    "$build/bin/imgcmp" $(edge "$rel") --put "$kept" "$new" || exit 1
    continue
  fi
  if [ ! -f "$kept" ]; then echo "missing: $kept (run make regen)"; stale=1; continue; fi
  # shellcheck disable=SC2046
  why=$("$build/bin/imgcmp" $(edge "$rel") "$kept" "$new") ||
    { echo "stale: $kept: ${why:-cannot compare} (run make regen if the change is meant)"; stale=1; }
done < <(find "$tmp/img" -name '*.png' | sort)

# Kept pictures no generator made.
while IFS= read -r kept; do
  rel=${kept#docs/img/}
  [ -f "$tmp/img/$rel" ] && continue
  case " $HAND_MADE " in *" $rel "*) continue ;; esac
  echo "docimg: $kept: no generator of tools/figures/docimg.sh makes it (add its generator, or remove it)"
  [ "$mode" = check ] && stale=1
done < <(find docs/img -name '*.png' | sort)
[ "$mode" = check ] && [ $stale = 0 ] && echo "check-docimg: every picture of docs/img/ is what its generator renders"
exit $stale
