#!/usr/bin/env bash
# For make regen (tools/figures/regen.sh): one source a derived file is made from,
# what was rewritten from it, and the hand-written places that name what
# changed in it since the last commit, to re-read by hand:
#   words   "the NAME" for each material, shape or light kind of a changed line
#           ("the red sphere", "the point light"), in the docs, README.md, the
#           steps' manifests (trace notes) and the tests' sources;
#   copies  lines of other files holding three numbers of a changed line in a
#           row (the scenes that copy it by hand, bench/spheres.pov's
#           <0.8, 0.15, 0.1>, the fuzzing seeds), beyond all-0/1 runs.
# Usage: tools/figures/regen-places.sh SOURCE "WRITTEN FILES (one a line)"
set -uo pipefail
src=$1 written=${2:-}
show=10  # places shown per kind; the rest counted

nw=$(grep -c . <<<"$written")
from=""
[ "$nw" -gt 0 ] && from=": rewrote $(head -n 6 <<<"$written" | paste -sd' ')$([ "$nw" -gt 6 ] && echo " ... ($nw files)")"
# The changed lines, as they were (the words and numbers the copies still hold).
old=$(git diff -U0 HEAD -- "$src" 2>/dev/null | sed -n 's/^-\([^-]\)/\1/p' | grep -v '^[[:space:]]*#')
if [ -z "$old" ]; then
  echo "* $src (no line changed since the last commit, but comments or added lines)$from"
  exit 0
fi
echo "* $src$from"
echo "    changed lines (before): $(head -n 3 <<<"$old" | sed 's/  */ /g' | paste -sd'|' | sed 's/|/ | /g')"

# The words: "the NAME" of a material, "the NAME SHAPE" of the objects using it,
# "the KIND light".
# A changed material is named by the shapes that use it in the scene now.
uses=$(awk '$1 != "material" { for (k = 1; k < NF; k++) if ($k == "material") print $(k + 1), $1 }' "$src" 2>/dev/null)
words=$(awk -v uses="$uses" '
  BEGIN { n = split(uses, u, "\n"); for (k = 1; k <= n; k++) { split(u[k], p, " "); shape[p[1]] = shape[p[1]] " " p[2] } }
  $1 == "material" { print $2 " material"; m = split(shape[$2], s, " "); for (k = 1; k <= m; k++) print $2 " " s[k] }
  $1 == "light" { print $2 " light" }
  { for (k = 1; k < NF; k++) if ($k == "material") print $(k + 1) " " $1 }' <<<"$old" | sort -u)
# (docs/instructors.md's example of this output left out)
files=$(git ls-files -- 'docs/*.md' README.md 'steps/*/step.mk' 'tests/*.c' 'tests/*.h' 2>/dev/null |
        grep -v -x docs/instructors.md)
while IFS= read -r w; do
  [ -n "$w" ] || continue
  # shellcheck disable=SC2086 # the file list
  hits=$(grep -n -i -w -E "the $w" $files 2>/dev/null)
  n=$(grep -c . <<<"$hits")
  [ "$n" -gt 0 ] || continue
  echo "    \"the $w\" ($n place(s)):"
  head -n "$show" <<<"$hits" | cut -c1-150 | sed 's/^/      /'
  [ "$n" -gt "$show" ] && echo "      ... and $((n - show)) more (grep -n -i -w 'the $w')"
done <<<"$words"

# The copies: three numbers of a changed line in a row, in another file.
copies=$(git ls-files -- scenes bench tests docs README.md 2>/dev/null |
  grep -v -E '\.(json|png|diff|c|h)$' | grep -v -x -e "$src" -e docs/instructors.md |
  xargs awk -v old="$old" '
    function nums(s,   out, n, k, t) {
      gsub(/[^0-9.eE+-]+/, " ", s); n = split(s, t, " "); out = " "
      for (k = 1; k <= n; k++) if (t[k] ~ /^[-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/) out = out t[k] " "
      return out
    }
    BEGIN {
      n = split(old, lines, "\n")
      for (i = 1; i <= n; i++) {
        m = split(nums(lines[i]), v, " ")
        for (k = 1; k + 2 <= m; k++) {
          if (v[k] v[k + 1] v[k + 2] ~ /^[-+]?[01]?[-+]?[01]?[-+]?[01]?$/) continue
          runs[" " v[k] " " v[k + 1] " " v[k + 2] " "] = 1
        }
      }
    }
    { s = nums($0); for (r in runs) if (index(s, r)) { print FILENAME ":" FNR ": " $0; break } }' 2>/dev/null)
n=$(grep -c . <<<"$copies")
if [ "$n" -gt 0 ]; then
  echo "    copies of its changed lines ($n line(s) in $(cut -d: -f1 <<<"$copies" | sort -u | wc -l) file(s)):"
  head -n "$show" <<<"$copies" | sed 's/  */ /g' | cut -c1-150 | sed 's/^/      /'
  [ "$n" -gt "$show" ] && echo "      ... and $((n - show)) more; the files: $(cut -d: -f1 <<<"$copies" | sort -u | paste -sd' ')"
fi
exit 0
