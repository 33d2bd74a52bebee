#!/usr/bin/env bash
# Carry a student's code forward: a step folder repeats the regions of earlier
# steps (steps/06-ambient/shade.c holds the step-04, 05 and 06 regions); copy
# the student's own code of every step below N, from the earliest step folder
# that has it, into steps/NN-*/ and every later step folder.
# Usage: tools/carry.sh N                 (make carry N; N = 2 .. 8)
#        tools/carry.sh --solution DIR K  write the solution tree DIR's code of
#                                         step K's regions where a student
#                                         writes it (common/, the earliest step
#                                         folder): tools/check-starter.sh plays
#                                         a student with it
# Nothing is written unless every region to copy is finished (no TODO(step NN)
# line left) and every marker is in place; a file whose region held different
# code of the student's is saved under carry-backup/ first.
# docs/instructors.md, "Carrying code forward"; tools/carry.awk reads the regions.
set -euo pipefail

usage() {
  echo "usage: make carry N   (N = 2 .. 8: copies your code of the steps below N into steps N .. 8)" >&2
  exit 2
}
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
awk_regions="$top/tools/carry.awk"

solution=""
if [ "${1:-}" = --solution ]; then
  [ $# -eq 3 ] || usage
  solution=$(cd "$2" && pwd) || exit 2
  shift 2
fi
[ $# -eq 1 ] && [[ "$1" =~ ^[0-9]+$ ]] || usage
n=$((10#$1))
if [ -n "$solution" ]; then [ $n -ge 1 ] && [ $n -le 8 ] || usage
else [ $n -ge 2 ] && [ $n -le 8 ] || usage; fi
nn=$(printf %02d $n)
later=$([ $n -eq 8 ] && echo "step 08" || echo "steps $nn to 08")

# The student's regions: one line per region, FILE FIRST LAST STEP KEY TODO.
regions_of() {
  local f
  for f in "$@"; do
    awk -v mode=list -f "$awk_regions" "$f" | sed "s|^|$f\t|" || return 1
  done
}
files=$(grep -l -E '/\* BEGIN step [0-9]{2}: ' common/*.[ch] common/*/*.[ch] steps/*/*.[ch] 2>/dev/null || true)
if [ -z "$files" ]; then
  if grep -q -E 'BEGIN SOLUTION step' common/*.[ch] steps/*/*.[ch] 2>/dev/null; then
    echo "carry: this is the solution tree (BEGIN SOLUTION markers): make carry works in a starter tree (make starter)" >&2
  else
    echo "carry: no '/* BEGIN step NN: ... */' markers found under common/ and steps/: is this a starter tree?" >&2
  fi
  exit 1
fi
table=$(regions_of $files) || {
  echo "carry: nothing copied: put the marker lines back as make starter wrote them (/* BEGIN step NN: NAME */ ... /* END step NN */ around each region)" >&2
  exit 1; }

# The regions make starter wrote (tools/starter-regions.tsv: FILE STEP KEY):
# each file must still have exactly those, or matching would be guesswork.
manifest=tools/starter-regions.tsv
if [ -f "$manifest" ] && [ -z "$solution" ]; then
  bad=$(awk -F'\t' '
    FNR == NR { want[$1 "\t" $3] = 1; next }
    { have[$1 "\t" $5] = 1 }
    END {
      for (k in want) if (!(k in have)) { split(k, p, "\t"); printf "%s: the region /* BEGIN step %s */ ... /* END step %s */ is gone (its marker lines removed or changed)\n", p[1], p[2], substr(p[2], 1, 2) }
      for (k in have) if (!(k in want)) { split(k, p, "\t"); printf "%s: a region /* BEGIN step %s */ that make starter did not write\n", p[1], p[2] }
    }' "$manifest" <(printf '%s\n' "$table") | sort)
  if [ -n "$bad" ]; then
    sed 's/^/carry: /' <<<"$bad" >&2
    echo "carry: nothing copied: put the marker lines back as make starter wrote them ($manifest lists every region)" >&2
    exit 1
  fi
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/carry.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# The folder's step number: steps/06-ambient/shade.c -> 06; common/... -> 00.
step_of() { case "$1" in steps/[0-9][0-9]-*) local s=${1#steps/}; echo "${s:0:2}" ;; *) echo 00 ;; esac; }
# Where a region is written first: common/'s file, else the lowest step folder
# with a region of that key in a file of that name. Prints FILE FIRST LAST TODO.
first_place() { # key basename
  awk -F'\t' -v key="$1" -v base="$2" '
    $5 == key { n = split($1, p, "/"); if (p[n] != base) next
                folder = $1 ~ /^steps\// ? p[2] : "" ; if (best == "" || folder < bestf) { best = $0; bestf = folder } }
    END { if (best != "") { split(best, b, "\t"); print b[1] "\t" b[2] "\t" b[3] "\t" b[6] } }' <<<"$table"
}
name_of() { local k=${1#*: }; echo "${k% #*}"; } # "04: shade_phong #2" -> shade_phong
body() { sed -n "$(($2 + 1)),$(($3 - 1))p" "$1"; } # file first last

# ---------------------------------------------------------------- --solution
if [ -n "$solution" ]; then
  # Step K's regions, each at its first place, get the solution's code (its
  # HINT and STUB lines dropped).
  declare -A done_key
  while IFS=$'\t' read -r f first last step key todo; do
    [ "$step" = "$nn" ] || continue
    place=$(first_place "$key" "${f##*/}")
    [ "${place%%$'\t'*}" = "$f" ] || continue
    [ -z "${done_key[$f $key]:-}" ] || continue
    done_key[$f $key]=1
    [ -f "$solution/$f" ] || { echo "carry: $solution/$f: no such file" >&2; exit 1; }
    sol=$(awk -v mode=list -f tools/stub.awk "$solution/$f" |
          awk -F'\t' -v key="$key" '
            function spoken(list, parts, n, k, s) { n = split(list, parts, ","); s = parts[1]
              for (k = 2; k <= n; k++) s = s (k == n ? " and " : ", ") parts[k]; return s }
            $4 ": " spoken($5) == key { print $2 "\t" $3; exit }')
    [ -n "$sol" ] || { echo "carry: $solution/$f has no region 'step $key'" >&2; exit 1; }
    idx=$(awk -F'\t' -v f="$f" -v first="$first" '$1 == f { k++; if ($2 == first) print k }' <<<"$table")
    mkdir -p "$tmp/$f.repl"
    sed -n "$((${sol%%$'\t'*} + 1)),$((${sol##*$'\t'} - 1))p" "$solution/$f" |
      grep -v -E '^[[:space:]]*/\* (STUB|HINT): .*\*/[[:space:]]*$' > "$tmp/$f.repl/$idx" || true
  done <<<"$table"
  for d in $(cd "$tmp" && find . -name '*.repl' -type d | sed 's|^\./||; s|\.repl$||'); do
    awk -v mode=replace -v repl="$tmp/$d.repl" -f "$awk_regions" "$d" > "$tmp/new" && cat "$tmp/new" > "$d"
  done
  exit 0
fi

# ---------------------------------------------------------------- make carry N
# Every region of a step below N in steps/NN-* or later that is not where the
# student wrote it first gets the code of that first place.
errors=0; copies=0; replaced=0; repeated=0
declare -A targets_of changed unfinished
replaced_msgs=()
while IFS=$'\t' read -r f first last step key todo; do
  folder=$(step_of "$f")
  [ "$folder" != 00 ] && [ $((10#$folder)) -ge $n ] && [ $((10#$step)) -lt $n ] || continue
  IFS=$'\t' read -r src sfirst slast stodo <<<"$(first_place "$key" "${f##*/}")"
  if [ "$src" = "$f" ]; then
    echo "carry: $f:$first: no earlier step folder has this step-$step region ($(name_of "$key")) to copy from: were its marker lines copied or changed?" >&2
    errors=$((errors + 1)); continue
  fi
  repeated=$((repeated + 1))
  if [ "$stodo" = 1 ]; then
    [ -n "${unfinished[$src:$sfirst]:-}" ] && continue
    unfinished[$src:$sfirst]=1
    echo "carry: $src:$sfirst: your step-$step region ($(name_of "$key")) is not finished: its TODO(step $step) line is still there. Finish it, delete that line, then make carry $n again." >&2
    errors=$((errors + 1)); continue
  fi
  body "$src" "$sfirst" "$slast" > "$tmp/src"
  body "$f" "$first" "$last" > "$tmp/dst"
  cmp -s "$tmp/src" "$tmp/dst" && continue
  idx=$(awk -F'\t' -v f="$f" -v first="$first" '$1 == f { k++; if ($2 == first) print k }' <<<"$table")
  mkdir -p "$tmp/$f.repl"
  cp "$tmp/src" "$tmp/$f.repl/$idx"
  copies=$((copies + 1))
  [ "${changed[$f]:-}" = 2 ] || changed[$f]=1
  targets_of["$src:$key"]+="${targets_of["$src:$key"]:+,} $f"
  if [ "$todo" = 0 ]; then # the student's own code there, different: keep a copy
    replaced=$((replaced + 1)); changed[$f]=2
    replaced_msgs+=("carry: $f:$first: your step-$step code there ($(name_of "$key")) differs from $src's: replaced by it (the old file is kept, see below)")
  fi
done <<<"$table"
# A folder between the first place and N keeps its own copy; say when it
# differs, in case a fix was made there instead of in the first place.
while IFS=$'\t' read -r f first last step key todo; do
  folder=$(step_of "$f")
  [ "$folder" != 00 ] && [ $((10#$folder)) -lt $n ] && [ $((10#$step)) -lt $n ] && [ "$todo" = 0 ] || continue
  IFS=$'\t' read -r src sfirst slast stodo <<<"$(first_place "$key" "${f##*/}")"
  [ "$src" != "$f" ] && [ "$stodo" = 0 ] || continue
  cmp -s <(body "$src" "$sfirst" "$slast") <(body "$f" "$first" "$last") && continue
  echo "carry: note: $f:$first has its own step-$step code ($(name_of "$key")), different from $src's, which is the one copied; if you fixed something there, fix it in $src and make carry $n again" >&2
done <<<"$table"
if [ $errors -gt 0 ]; then
  echo "carry: nothing copied ($errors problem(s) above)" >&2
  exit 1
fi
if [ $repeated -eq 0 ]; then
  echo "carry: nothing to copy: no step folder from $nn on repeats a region of the steps below $nn (that code is in common/ or in its own step's folder, used as it is)"
  exit 0
elif [ $copies -eq 0 ]; then
  echo "carry: nothing to copy: $later already $([ $n -eq 8 ] && echo holds || echo hold) your code of the steps below $nn"
  exit 0
fi

[ ${#replaced_msgs[@]} -eq 0 ] || printf '%s\n' "${replaced_msgs[@]}"

# Every new file is written in $tmp first; then backups, then the files.
for f in "${!changed[@]}"; do
  awk -v mode=replace -v repl="$tmp/$f.repl" -f "$awk_regions" "$f" > "$tmp/$f.new"
done
backup=""
for f in "${!changed[@]}"; do
  [ "${changed[$f]}" = 2 ] || continue
  if [ -z "$backup" ]; then # a folder of its own, even for two runs in a second
    backup=carry-backup/$(date +%Y%m%d-%H%M%S)
    k=1; suffix=""
    while [ -e "$backup$suffix" ]; do k=$((k + 1)); suffix=-$k; done
    backup=$backup$suffix
  fi
  mkdir -p "$backup/$(dirname "$f")"
  cp -p "$f" "$backup/$f"
done
for f in "${!changed[@]}"; do cat "$tmp/$f.new" > "$f"; done
for k in "${!targets_of[@]}"; do
  key=${k#*:}
  echo "carry: step ${key%%:*} ($(name_of "$key")) from ${k%%:*} ->${targets_of[$k]}"
done | sort
echo "carry: $copies region(s) copied into $later$( [ -n "$backup" ] && echo "; $replaced held different code of yours: the files as they were are in $backup/" )"
