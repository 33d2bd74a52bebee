# Sourced by tools/grading/report.sh: the student pages and the class page
# (static HTML, no script; docs/grading.md, "Outputs").

esc() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g' -e 's/"/\&quot;/g'; }

# The student report's look (tools/loop/report.html's style: verdicts, pictures,
# the flip), and the few rules the grader's tables and bars add.
page_head() {
  cat <<EOF
<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>$(printf '%s' "$1" | esc)</title>
<style>
EOF
  sed -n '/<style>/,/<\/style>/p' "$GRADE_BASE/solved/tools/loop/report.html" | sed '1d;$d'
  cat <<'EOF'
h1 small, h2 small { color: #666; font-weight: normal; }
table.grade { border-collapse: collapse; margin: 0.5em 0 1em; }
table.grade td, table.grade th { border: 1px solid #ccc; padding: 0.1em 0.6em; text-align: left; vertical-align: top; }
.bar { background: #4a78b5; height: 1em; display: inline-block; vertical-align: middle; }
</style>
</head>
<body>
EOF
}

# info_get STUDENT_DIR KEY: a value of the student's info.tsv.
info_get() { awk -F'\t' -v k="$2" '$1 == k { print $2; exit }' "$1/info.tsv" 2>/dev/null; }

# The student's scores for STEP: CHECK STATUS POINTS MAX WHY.
step_rows() {
  awk -F'\t' -v who="$2" -v s="$3" 'FILENAME == ARGV[1] { max[$1] = $2; next }
    $1 == who && index($2, s "/") == 1 { printf "%s\t%s\t%s\t%s\t%s\n", $2, $3, $4, max[$2], $5 }' \
    "$1/points.tsv" "$1/scores.tsv"
}

# picture_block DIR CHECK LINE STATUS: expected | yours | difference and a
# flip between the first two (the markup of the student report,
# tools/loop/report.c), the numbers, and for a failing check the --trace command
# of its worst pixel. Pictures at their own size.
picture_block() {
  local d=$1 c=$2 line=$3 status=$4 kv p step=${2%%/*} id
  declare -A v
  for kv in $line; do v[${kv%%=*}]=${kv#*=}; done
  p=pictures/$(slug "$c")
  id=flip-$(slug "$c")
  [ -f "$d/$p-yours.png" ] || return 0
  echo "<div class=\"pictures\">"
  for k in expected yours diff; do
    printf '<figure><img src="%s-%s.png" alt="%s: %s"><figcaption>%s</figcaption></figure>\n' "$p" "$k" \
      "$c" "$k" "$( [ $k = diff ] && echo 'difference (x8, red: over)' || echo $k)"
  done
  printf '<figure class="flip"><input type="checkbox" id="%s"><div class="stack">' "$id"
  printf '<img class="yours" src="%s-yours.png" alt="yours"><img class="expected" src="%s-expected.png" alt="expected">' "$p" "$p"
  printf '</div><figcaption><label for="%s">flip: hover or click to see <span class="to-expected">expected</span>' "$id"
  echo '<span class="to-yours">yours</span></label></figcaption></figure></div>'
  echo "<p>$(printf '%s' "$c" | esc)"
  if [ "$status" = FAIL ]; then
    local cmd="build/bin/$step"
    case $c in
      */reference_image) cmd="$cmd --width ${v[size]%x*} --height ${v[size]#*x}$(
                           a=$("$GRADE_BASE/solved/tools/build/manifest.sh" get "$step" IMAGE_ARGS 2>/dev/null); echo "${a:+ $a}")" ;;
      */hidden/*) cmd="$cmd --scene ${c##*/}.scene --seed $(awk -F'\t' -v c="$c" '$1 == c { print $5 }' "$GRADE_PLAN")" ;;
    esac
    echo ": the largest difference is at pixel (${v[worst_x]}, ${v[worst_y]}) (x from the left, y from the top);"
    echo "trace it: <code>$cmd --trace ${v[worst_x]} ${v[worst_y]}</code>"
  fi
  echo "</p>"
}

student_page() {
  local out=$1 st=$2 d=$1/students/$2 total max s
  total=$(awk -F'\t' -v w="$st" '$1 == w { t += $4 } END { print t + 0 }' "$out/scores.tsv")
  max=$(awk -F'\t' '{ t += $2 } END { print t + 0 }' "$out/points.tsv")
  page_head "$st: $total / $max"
  echo "<p><a href=\"../../index.html\">class</a></p>"
  echo "<h1>$(printf '%s' "$st" | esc) <small>$total / $max points</small></h1>"
  echo "<table class='grade'>"
  for k in kind source host sandbox build build_seconds stubbed uncut reused seconds; do
    case $k in stubbed|uncut) [ -n "$(info_get "$d" $k)" ] || continue ;; esac
    printf '<tr><th>%s</th><td>%s</td></tr>\n' "${k//_/ }" "$(info_get "$d" $k | esc)"
  done
  echo "</table>"
  student_files "$d"
  student_build "$d"
  for s in $(cat "$GRADE_BASE/steps.txt") stress; do student_step "$out" "$st" "$s"; done
  echo "</body></html>"
}

student_files() {
  local d=$1
  [ -s "$d/files.tsv" ] || return 0
  echo "<h2>Files</h2><p>Taken from the submission: the files that hold solution regions." \
       "Everything else comes from the instructor's tree.</p><ul>"
  awk -F'\t' '$2 == "missing" { print "<li><code>" $1 "</code>: not in the submission, graded as the starter&apos;s stub</li>" }
              $2 == "changed" { print "<li><code>" $1 "</code>: changed by the submission, <b>not used</b></li>" }
              $2 == "added" { print "<li><code>" $1 "</code>: added by the submission, not used</li>" }
              $2 == "link" { print "<li><code>" $1 "</code>: a symbolic link, not used</li>" }' \
    "$d/files.tsv" | sed 's/&apos;/\&#39;/'
  echo "</ul>"
}

student_build() {
  local d=$1
  [ -f "$d/build.log" ] && grep -q 'error' "$d/build.log" || return 0
  echo "<details open><summary>Build errors</summary><pre>"
  grep -E -A3 'error|Error' "$d/build.log" | head -n 40 | esc
  echo "</pre></details>"
}

student_step() {
  local out=$1 st=$2 s=$3 d=$1/students/$2 c status pts max why got all
  got=$(step_rows "$out" "$st" "$s" | awk -F'\t' '{ g += $3; m += $4 } END { print g + 0 "/" m + 0 }')
  echo "<h2 id=\"$s\">$s <small>${got%/*} / ${got#*/} points</small></h2>"
  echo "<table class='grade'><tr><th>check</th><th>verdict</th><th>points</th><th>why</th></tr>"
  while IFS=$'\t' read -r c status pts max why; do
    printf '<tr><td>%s</td><td><span class="%s">%s</span></td><td>%s / %s</td><td>%s</td></tr>\n' \
      "$(printf '%s' "$c" | esc)" "$(echo "$status" | tr A-Z a-z)" "$status" "$pts" "$max" \
      "$(printf '%s' "$why" | esc)"
  done < <(step_rows "$out" "$st" "$s")
  echo "</table>"
  while IFS=$'\t' read -r c status pts max why; do
    [ -f "$d/details/$(slug "$c").txt" ] || continue
    echo "<details open><summary>$(printf '%s' "$c" | esc): the failing tests</summary><pre>"
    head -c 20000 "$d/details/$(slug "$c").txt" | esc
    echo "</pre></details>"
  done < <(step_rows "$out" "$st" "$s")
  [ -f "$d/pictures.tsv" ] || return 0
  while IFS=$'\t' read -r c line; do
    [ "${c%%/*}" = "$s" ] || continue
    status=$(awk -F'\t' -v c="$c" '$1 == c { print $2 }' "$d/checks.tsv")
    picture_block "$d" "$c" "$line" "$status"
  done <"$d/pictures.tsv"
}

class_page() {
  local out=$1 n max
  n=$(cut -f1 "$out/scores.tsv" | sort -u | grep -c . || true)
  max=$(awk -F'\t' '{ t += $2 } END { print t + 0 }' "$out/points.tsv")
  page_head "Class: $n submissions"
  echo "<h1>Class <small>$n submissions, $max points</small></h1>"
  class_histogram "$out" "$max"
  class_steps "$out" "$n"
  class_failing "$out" "$n"
  class_students "$out" "$max"
  echo "</body></html>"
}

# Totals in ten bins of the maximum, as bars.
class_histogram() {
  echo "<h2>Scores</h2><table class='grade'><tr><th>points</th><th>students</th></tr>"
  awk -F'\t' -v max="$2" '{ t[$1] += $4 }
    END { for (w in t) { b = max > 0 ? int(10 * t[w] / max) : 10; if (b > 9) b = 9; h[b]++; if (h[b] > top) top = h[b] }
          for (b = 0; b < 10; b++) printf "<tr><td>%g &ndash; %g%s</td><td><span class=\"bar\" style=\"width:%dpx\"></span> %d</td></tr>\n",
            b * max / 10, (b + 1) * max / 10, b == 9 ? "" : " (excl.)", top ? 300 * h[b] / top : 0, h[b] }' "$1/scores.tsv"
  echo "</table>"
}

# Per step: students passing every check of it, and each check's pass rate.
class_steps() {
  echo "<h2>Steps</h2><table class='grade'><tr><th>step</th><th>passing every check</th><th>checks (pass rate)</th></tr>"
  awk -F'\t' -v n="$2" '{ split($2, p, "/"); s = p[1]
      if (!(s in seen)) { seen[s] = 1; order[++k] = s }
      if (!(($2) in cseen)) { cseen[$2] = 1; corder[s] = corder[s] " " $2 }
      if ($3 == "PASS") pass[$2]++; else bad[s "\t" $1] = 1; who[$1] = 1 }
    END { for (i = 1; i <= k; i++) { s = order[i]; ok = 0
            for (w in who) if (!((s "\t" w) in bad)) ok++
            m = split(corder[s], cs, " "); line = ""
            for (j = 1; j <= m; j++) { c = cs[j]; sub("^" s "/", "", c)
              line = line sprintf("%s%s %d%%", j > 1 ? ", " : "", c, n ? 100 * pass[cs[j]] / n : 0) }
            printf "<tr><td>%s</td><td>%d of %d (%d%%)</td><td>%s</td></tr>\n", s, ok, n, n ? 100 * ok / n : 0, line } }' \
    "$1/scores.tsv"
  echo "</table>"
}

# The checks that fail most often, with their most common reason (reasons
# compared with their numbers left out; one of them shown as it reads).
class_failing() {
  echo "<h2>Most common failing checks</h2><table class='grade'><tr><th>check</th><th>failing</th><th>most common reason</th></tr>"
  awk -F'\t' '$3 != "PASS" { f[$2]++; k = $5; gsub(/[0-9][0-9.]*/, "#", k)
                             r[$2 "\t" k]++; if (!(($2 "\t" k) in ex)) ex[$2 "\t" k] = $5 }
    END { for (c in f) { best = 0; why = ""
            for (k in r) { split(k, p, "\t"); if (p[1] == c && r[k] > best) { best = r[k]; why = ex[k] } }
            printf "%d\t%s\t%s\n", f[c], c, why } }' "$1/scores.tsv" | sort -t$'\t' -k1,1nr -k2,2 | head -n 15 |
    while IFS=$'\t' read -r k c why; do
      printf '<tr><td>%s</td><td>%d of %d</td><td>%s</td></tr>\n' "$(printf '%s' "$c" | esc)" "$k" "$2" \
        "$(printf '%s' "$why" | esc)"
    done
  echo "</table>"
}

class_students() {
  echo "<h2>Students</h2><table class='grade'><tr><th>student</th><th>points</th><th>failing checks</th></tr>"
  awk -F'\t' '{ t[$1] += $4; if ($3 != "PASS") f[$1] = f[$1] (f[$1] == "" ? "" : ", ") $2; w[$1] = 1 }
    END { for (s in w) printf "%s\t%s\t%s\n", s, t[s], f[s] }' "$1/scores.tsv" | sort |
    while IFS=$'\t' read -r s t f; do
      printf '<tr><td><a href="students/%s/index.html">%s</a></td><td>%s / %s</td><td>%s</td></tr>\n' \
        "$s" "$s" "$t" "$2" "$(printf '%s' "${f:-none}" | esc)"
    done
  echo "</table>"
}
