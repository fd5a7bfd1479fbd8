#!/usr/bin/env bash
# On the lent GPU machine: builds the CUDA test binary and blaze (make -j16: ~7.5 min on the
# H100 machine's 16 cores), then runs every suite of the binary as its own process, N at a time
# under MPS (default 8), each given the time left of BUDGET seconds (default 540) so that the
# call ends inside the device's 10-minute limit; suites that got no time are named. Their rows go
# to $OUT/verification.tsv (the table's GPU column: verification/results/<device>.tsv). A suite
# that ran out of time is listed with rc=124; run it again in the next call while the machine is
# warm (the build stays for 30 s after a call): tools/gpu_all_suites.sh --no-build SUITE...
# Usage: tools/gpu_all_suites.sh [--no-build] [SUITE...]   (no suite: all of them)
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/blaze-gpu}; mkdir -p "$out"
T0=$(date +%s); left() { echo $(( ${BUDGET:-540} - ($(date +%s) - T0) )); }
. tools/device_env.sh
build=1; [ "${1:-}" = "--no-build" ] && { build=0; shift; }
if [ $build = 1 ]; then
  make -j"$(nproc)" build/cuda/blaze_tests build/cuda/blaze build/cuda/study_hopper > "$out/build.log" 2>&1 || { tail -30 "$out/build.log"; exit 1; }
  echo "build: $(( $(date +%s) - T0 )) s"
fi
B=build/cuda/blaze_tests
suites=${*:-$($B --list_content 2>&1 | grep -v "^ " | sed 's/\*$//')}
nvidia-cuda-mps-control -d 2>/dev/null
rep=$(mktemp -d)
for s in $suites; do
  while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-8}" ]; do sleep 1; done
  t=$(left); [ "$t" -lt 15 ] && { echo "suite $s: no time left"; continue; }
  ( BLAZE_REPORT=$rep/$s.tsv timeout "$t" $B --run_test="$s" --report_level=short --color_output=no > "$rep/$s.log" 2>&1
    echo "suite $s rc=$? $(grep -a 'test cases' "$rep/$s.log" | head -1 | tr -s ' ') $(( $(date +%s) - T0 )) s" ) &
done
wait
cat "$rep"/*.tsv > "$out/verification.tsv" 2>/dev/null
grep -a "error:" "$rep"/*.log | head -20
