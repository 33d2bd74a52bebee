#!/usr/bin/env bash
# The report in a real browser (docs/tracing.md, "The report"), run by make
# check-report after make test wrote BUILD/report/index.html. Headless
# Chromium renders two reports to screenshots and tools/check/report-check.c finds
# every picture of the page in them (a missing or broken picture shows as a
# small icon instead):
#   1. BUILD/report/index.html, the one make test just wrote;
#   2. a scratch copy (BUILD/report-test) where step 03 passes and step 04
#      fails: its reference pictures are rendered from step 04's scene (its
#      manifest's SCENE) whose first material with a specular term lost it, so
#      the image test fails and compares the terms. When no material of that
#      scene has a specular term, the check fails and says so.
# Usage: tests/report.sh BUILD. Prints one verdict line per report; exit 1
# when a picture is not shown. Without chromium it says SKIP and exits 0.
set -uo pipefail
build=${1:?usage: tests/report.sh BUILD}
browser=$(command -v chromium || true)
if [ -z "$browser" ]; then
  echo "SKIP  report in a browser: chromium is not installed (make check installs it when"
  echo "      run as root; otherwise: sudo apt-get install chromium)"
  exit 0
fi

# A profile of its own: two runs at once (make -j2 sanitize runs gcc's and
# clang's suites side by side) would otherwise share the user's.
profile=$(mktemp -d "${TMPDIR:-/tmp}/report-test.XXXXXX")
trap 'rm -rf "$profile"' EXIT

# shot PAGE PNG HEIGHT: the page at 1400 x HEIGHT pixels, one device pixel each.
shot() {
  "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$profile" \
    --force-device-scale-factor=1 --window-size=1400,"$3" --screenshot="$2" \
    "file://$(realpath "$1")" > /dev/null 2>&1
}

# check WHAT PAGE PNG HEIGHT: one verdict line.
check() {
  rm -f "$3"
  if ! shot "$2" "$3" "$4" || [ ! -s "$3" ]; then
    echo "FAIL  report in a browser: $1: chromium wrote no screenshot of $2"; return 1
  fi
  if out=$("$build/bin/report-check" "$2" "$3"); then
    echo "PASS  report in a browser: $1: ${out#report-check: }"
  else
    echo "FAIL  report in a browser: $1:"; echo "$out" | sed 's/^/      /'; return 1
  fi
}

status=0
check "make test's report" "$build/report/index.html" "$build/report/screenshot.png" 9000 ||
  status=1

# The scratch copy: the test binaries and programs of BUILD, its own outputs.
scratch=$build/report-test
rm -rf "$scratch"
mkdir -p "$scratch/$build" "$scratch/tools/loop" "$scratch/tests"
for d in bin tests; do ln -s "$(realpath "$build/$d")" "$scratch/$build/$d"; done
cp -r images "$scratch/"
cp tools/loop/report.html "$scratch/tools/loop/"
cp tests/run.sh tests/results.awk "$scratch/tests/"
scene=$(tools/build/manifest.sh get 04-phong SCENE) && size=$(tools/build/manifest.sh get 04-phong IMAGE_SIZE) &&
  args=$(tools/build/manifest.sh get 04-phong IMAGE_ARGS) && terms=$(tools/build/manifest.sh get 04-phong IMAGE_TERMS) ||
  { echo "FAIL  report in a browser: cannot read steps/04-phong/step.mk"; exit 1; }
# The first material line with "specular R G B shininess N", without them.
awk '!done && $1 == "material" && / specular [-0-9.e]+ [-0-9.e]+ [-0-9.e]+ shininess [0-9.e]+/ {
       sub(/ +specular [-0-9.e]+ [-0-9.e]+ [-0-9.e]+ shininess [0-9.e]+/, ""); done = 1 }
     { print }' "$scene" > "$scratch/broken.scene"
if cmp -s "$scene" "$scratch/broken.scene"; then
  echo "FAIL  report in a browser: the scratch report's failing step 04 needs a material with a"
  echo "      specular term in $scene (step 04's SCENE): no 'material NAME ... specular R G B"
  echo "      shininess N' line there; give tests/report.sh a scene that has one"; exit 1
fi
for what in "" $terms; do
  # shellcheck disable=SC2086 # options
  "$build/bin/04-phong" --scene "$scratch/broken.scene" --width "${size% *}" --height "${size#* }" \
    --threads 2 --quiet $args ${what:+--aov $what} -o "$scratch/images/04-phong${what:+.$what}.png" || exit 1
done
(cd "$scratch" && RT_CACHE=0 tests/run.sh "$build/tests/03-camera" "$build/tests/04-phong" > run.log 2>&1
 "$build/bin/report" "$build" tools/loop/report.html > /dev/null)
page=$scratch/$build/report/index.html
if ! grep -q '<h2>03-camera <span class="pass">' "$page" ||
   ! grep -q '<h2>04-phong <span class="fail">' "$page"; then
  echo "FAIL  report in a browser: the scratch report should show 03-camera PASS and 04-phong"
  echo "      FAIL ($page; the tests said: $scratch/run.log)"; status=1
fi
check "a passing step (03) and a failing one (04)" "$page" "$scratch/$build/report/screenshot.png" \
  3200 || status=1
exit $status
