#!/usr/bin/env bash
# make test-grade-slurm (docs/grading.md, "On a few hosts, on a cluster"): a one-node Slurm
# started here (munged with a fresh key, slurmctld and slurmd as root, on
# ports of their own), the sample class graded through the job array
# (tools/grading/grade SLURM=1), grades.csv compared with the local grading's, and
# the daemons this script started stopped again. Skips, saying why, where
# Slurm cannot start.
# Usage: tools/grading/slurm-test.sh CLASS HIDDEN LOCAL_OUT
set -uo pipefail

[ $# = 3 ] || { echo "usage: tools/grading/slurm-test.sh CLASS HIDDEN LOCAL_OUT" >&2; exit 2; }
class=$(realpath -- "$1") hidden=$(realpath -- "$2") local_out=$(realpath -- "$3")
top=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
cd "$top"
skip() { echo "test-grade-slurm: SKIPPED: $*"; exit 0; }
[ "$(id -u)" = 0 ] || skip "the test starts slurmctld, slurmd and munged as root; run it as root"
for c in munged slurmctld slurmd sbatch sinfo; do
  command -v $c >/dev/null || skip "$c is missing (make test-grade-slurm installs slurm-wlm and munge as root)"
done

dir=$(mktemp -d "${TMPDIR:-/tmp}/slurm-test.XXXXXX")
chmod 755 "$dir"
pids=()
stop() {
  local p
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null; done
  rm -rf "$dir"
}
trap stop EXIT
mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/log"
chmod 700 "$dir/munge"

# munged with a fresh key, on a socket of its own.
dd if=/dev/urandom of="$dir/munge/key" bs=1024 count=1 status=none
chmod 400 "$dir/munge/key"
munged --foreground --force --key-file="$dir/munge/key" --socket="$dir/munge/socket" \
  --pid-file="$dir/munge/pid" --log-file="$dir/log/munged.log" --seed-file="$dir/munge/seed" \
  >"$dir/log/munged.out" 2>&1 &
pids+=($!)

host=$(hostname -s)
cat >"$dir/slurm.conf" <<EOF
ClusterName=grade-test
SlurmctldHost=$host
SlurmUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$dir/munge/socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=grade Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$dir/slurm.conf
for i in $(seq 50); do [ -S "$dir/munge/socket" ] && break; sleep 0.1; done
[ -S "$dir/munge/socket" ] || skip "munged did not start ($(tail -n 1 "$dir/log/munged.log" 2>/dev/null))"
slurmctld -D -i >"$dir/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D >"$dir/log/slurmd.out" 2>&1 &
pids+=($!)
for i in $(seq 100); do
  sinfo -h -o %t 2>/dev/null | grep -qx idle && break
  sleep 0.2
done
sinfo -h -o %t 2>/dev/null | grep -qx idle ||
  skip "slurmctld and slurmd did not come up: $(tail -n 2 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" 2>/dev/null | tr '\n' ' ')"
echo "test-grade-slurm: Slurm $(sinfo -V | cut -d' ' -f2) up on $host ($(nproc) CPUs)"

t0=$(date +%s)
GRADE_CACHE="$local_out/cache" tools/grading/grade SLURM=1 SUBMISSIONS="$class" HIDDEN="$hidden" OUT="$dir/out" ||
  { echo "test-grade-slurm: tools/grading/grade SLURM=1 failed"; exit 1; }
t=$(( $(date +%s) - t0 ))
# The local grading's rows of the same students, header included.
want=$(awk -F, 'FILENAME == ARGV[1] { w[$1] = 1; next } $1 in w' "$dir/out/grades.csv" "$local_out/grades.csv" | sort)
got=$(sort "$dir/out/grades.csv")
if [ "$want" != "$got" ]; then
  diff <(echo "$want") <(echo "$got") >"$dir/diff"
  echo "test-grade-slurm: FAIL: the Slurm array's grades.csv differs from the local grading's:"
  cat "$dir/diff"
  exit 1
fi
tasks=$(ls "$dir/out/slurm" | grep -c .)
echo "test-grade-slurm: PASS: $tasks array tasks in $t s gave the local grades.csv, row for row"
