#!/usr/bin/env bash
# Run Criterion test binaries one after the other and end with one synthesis
# line over all of them. Usage: tests/run.sh [--verbose] BIN...
# Exit status: 0 when every test of every binary passed, 1 otherwise.
set -uo pipefail
verbose=()
if [ "${1:-}" = --verbose ]; then verbose=(--verbose); shift; fi
tested=0; passing=0; failing=0; crashing=0; status=0
for bin in "$@"; do
  log=$(mktemp)
  echo "==> ${bin##*/}"
  "$bin" "${verbose[@]}" 2>&1 | tee "$log"
  rc=${PIPESTATUS[0]}
  line=$(grep 'Synthesis: Tested:' "$log" | tail -n 1 | sed 's/\x1b\[[0-9;]*m//g')
  rm -f "$log"
  if [ -z "$line" ]; then
    echo "tests/run.sh: ${bin##*/} printed no synthesis (exit $rc)"; status=1; crashing=$((crashing + 1)); continue
  fi
  read -r t p f c < <(sed -E 's/.*Tested: ([0-9]+).*Passing: ([0-9]+).*Failing: ([0-9]+).*Crashing: ([0-9]+).*/\1 \2 \3 \4/' <<<"$line")
  tested=$((tested + t)); passing=$((passing + p)); failing=$((failing + f)); crashing=$((crashing + c))
  [ "$rc" -eq 0 ] || status=1
done
[ $((failing + crashing)) -eq 0 ] || status=1
echo
echo "[====] Synthesis: Tested: $tested | Passing: $passing | Failing: $failing | Crashing: $crashing"
exit $status
