#!/usr/bin/env bash
# make test-grade-ssh (docs/grading.md, "On a few hosts"): two submissions of
# the sample class graded through GNU parallel's --sshlogin on two host names,
# with a stand-in for ssh that runs the command here (as ssh would on a host
# that shares the folders) and notes the host; both hosts must have been used
# and the grades must be those of the local grading.
# Usage: tools/grading/ssh-test.sh CLASS HIDDEN LOCAL_OUT
set -uo pipefail

[ $# = 3 ] || { echo "usage: tools/grading/ssh-test.sh CLASS HIDDEN LOCAL_OUT" >&2; exit 2; }
class=$(realpath -- "$1") hidden=$(realpath -- "$2") local_out=$(realpath -- "$3")
top=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
cd "$top"
command -v parallel >/dev/null || { echo "test-grade-ssh: SKIPPED: GNU parallel is missing (make grade-deps)"; exit 0; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/ssh-test.XXXXXX")
trap 'rm -rf "$dir"' EXIT
mkdir -p "$dir/class"
for s in flipped-rows.tar.gz shadow-no-tmax; do ln -s "$class/$s" "$dir/class/$s"; done

# ssh [options] HOST [--] COMMAND...: the remote shell runs the words joined.
cat >"$dir/ssh" <<EOF
#!/usr/bin/env bash
while [ \$# -gt 0 ]; do case \$1 in -*) shift ;; *) break ;; esac; done
host=\$1
shift; [ "\${1:-}" = -- ] && shift
case "\$*" in *GNU_Parallel_worker*) echo "\$host" >>"$dir/hosts" ;; esac
exec bash -c "\$*"
EOF
chmod +x "$dir/ssh"
GRADE_SSH=$dir/ssh GRADE_CACHE=$local_out/cache tools/grading/grade SSHLOGIN=1/alpha,1/beta \
  SUBMISSIONS="$dir/class" HIDDEN="$hidden" OUT="$dir/out" >"$dir/log" 2>&1 ||
  { cat "$dir/log"; echo "test-grade-ssh: FAIL: tools/grading/grade SSHLOGIN=... failed"; exit 1; }
hosts=$(sort -u "$dir/hosts" | tr '\n' ' ')
[ "$hosts" = "alpha beta " ] || { echo "test-grade-ssh: FAIL: jobs went to: $hosts (expected alpha and beta)"; exit 1; }
want=$(grep -E '^(flipped-rows|shadow-no-tmax),' "$local_out/grades.csv")
got=$(grep -E '^(flipped-rows|shadow-no-tmax),' "$dir/out/grades.csv")
[ "$want" = "$got" ] || { echo "test-grade-ssh: FAIL: grades differ from the local grading:"; diff <(echo "$want") <(echo "$got"); exit 1; }
echo "test-grade-ssh: PASS: 2 submissions graded on hosts alpha and beta through parallel --sshlogin, grades as the local grading's"
