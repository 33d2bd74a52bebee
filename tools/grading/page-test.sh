#!/usr/bin/env bash
# make test-grade's check of the grader's pages in a browser (docs/grading.md,
# "Outputs"): headless Chromium loads the class page and the pages of the
# students named, each from a copy with a script that counts the pictures the
# browser decoded (the pages themselves have none); every <img> of a page
# must be decoded, and, with REPORT_CHECK (the student report's checker,
# tools/check/report-check.c), found pixel for pixel in the page's screenshot. The
# class page must link every student. Screenshots go to OUT/screenshots/.
# Without chromium it says SKIP and exits 0.
# Usage: [REPORT_CHECK=build/bin/report-check] tools/grading/page-test.sh OUT STUDENT...
set -uo pipefail

[ $# -ge 2 ] || { echo "usage: tools/grading/page-test.sh OUT STUDENT..." >&2; exit 2; }
out=$(realpath -- "$1")
shift
browser=$(command -v chromium || true)
if [ -z "$browser" ]; then
  echo "SKIP  grader pages in a browser: chromium is not installed (make check installs it when run as"
  echo "      root; otherwise: sudo apt-get install chromium)"
  exit 0
fi
profile=$(mktemp -d "${TMPDIR:-/tmp}/page-test.XXXXXX")
trap 'rm -rf "$profile"' EXIT
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --hide-scrollbars --user-data-dir="$profile")
mkdir -p "$out/screenshots"

# check NAME PAGE HEIGHT: one verdict line; 1 when a picture is not shown.
check() {
  local name=$1 page=$2 copy dom want loaded total broken
  copy=${page%.html}.check.html
  sed 's|</body>|<script>window.addEventListener("load", function () { var i, n = 0, bad = [];\
for (i = 0; i < document.images.length; i++) { var m = document.images[i];\
if (m.complete \&\& m.naturalWidth > 0) n++; else bad.push(m.getAttribute("src")); }\
document.body.setAttribute("data-images", document.images.length);\
document.body.setAttribute("data-loaded", n); document.body.setAttribute("data-broken", bad.join(" ")); });\
</script></body>|' "$page" >"$copy"
  dom=$(timeout 60 "$browser" "${flags[@]}" --virtual-time-budget=5000 --dump-dom "file://$copy" 2>/dev/null)
  rm -f "$copy"
  timeout 120 "$browser" "${flags[@]}" --force-device-scale-factor=1 --window-size=1400,"$3" \
    --screenshot="$out/screenshots/$name.png" "file://$page" >/dev/null 2>&1
  want=$(grep -o '<img ' "$page" | grep -c .)
  total=$(sed -n 's/.*<body[^>]* data-images="\([0-9]*\)".*/\1/p' <<<"$dom")
  loaded=$(sed -n 's/.*<body[^>]* data-loaded="\([0-9]*\)".*/\1/p' <<<"$dom")
  broken=$(sed -n 's/.*<body[^>]* data-broken="\([^"]*\)".*/\1/p' <<<"$dom")
  if [ -z "$total" ]; then
    echo "FAIL  grader pages in a browser: $name: chromium did not load $page"; return 1
  elif [ "$total" != "$want" ] || [ "$loaded" != "$want" ]; then
    echo "FAIL  grader pages in a browser: $name: $loaded of $want pictures shown; not shown: $broken"; return 1
  fi
  if [ -n "${REPORT_CHECK:-}" ] && [ "$want" -gt 0 ] &&
     ! shown=$("$REPORT_CHECK" "$page" "$out/screenshots/$name.png" 2>&1); then
    echo "FAIL  grader pages in a browser: $name: ${shown#report-check: }"; return 1
  fi
  echo "PASS  grader pages in a browser: $name: all $want pictures shown (screenshots/$name.png)"
}

status=0
check class "$out/index.html" 3000 || status=1
for st in "$@"; do
  grep -q "href=\"students/$st/index.html\"" "$out/index.html" ||
    { echo "FAIL  grader pages in a browser: the class page does not link $st"; status=1; }
  check "$st" "$out/students/$st/index.html" 16000 || status=1
done
exit $status
