#!/usr/bin/env bash
# On the lent GPU machine: make fig-2.17 (tools/corn_arching.sh) in device calls of under 10
# minutes. Each call builds study_hopper if needed (~250 s on 16 cores, the first call only: the
# build and the runs stay on a warm machine between calls), runs the twelve corn runs side by side
# under MPS and stops them at a checkpoint after STOP seconds (default 500); the next call continues
# them bitwise. The runs live in build/corn (kept between calls like any build output). Every call
# returns the runs' logs and time series (no frames) in $OUT/corn.tgz; the call in which all have
# ended also returns studies/hopper/corn.md, summary.csv and plots/fig-2.17.png.
# The study (~30 min of an H100 for the twelve) outlasts a session's device time, so every call
# also returns the runs' whole state but the frames (checkpoints, logs, time series, .pvd) as
# $OUT/corn-state.tgz.00, .01, ... (15 MiB parts); put them in build/corn-carry/ here
# (`mkdir -p build/corn-carry && cp FILES_AT/corn-state.tgz.* build/corn-carry/`) and carry that
# folder in a later session's call: a machine without build/corn unpacks it and continues the runs
# from their checkpoints (a run finished before keeps its results and its checkpoint is dropped).
# Usage: tools/gpu_corn.sh [STOP]        (JOBS=N: side by side, default 12; CORN_SEEDS as in
#   corn_arching.sh; CORN_PREBUILT=1 runs a carried build/cuda/study_hopper without make)
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/blaze-gpu}; mkdir -p "$out"
. tools/device_env.sh
T0=$(date +%s)
# CORN_PREBUILT=1: a study_hopper built elsewhere with the same nvcc and carried (saves ~250 s of
# device time; its Boost libraries travel in .devdeps: libboost-{iostreams,filesystem,system}1.74.0)
if [ -n "${CORN_PREBUILT:-}" ] && [ -x build/cuda/study_hopper ] && ! ldd build/cuda/study_hopper | grep "not found"; then
  echo "study_hopper: carried"
else
  make -j"$(nproc)" build/cuda/study_hopper > "$out/build.log" 2>&1 || { tail -30 "$out/build.log"; exit 1; }
fi
echo "study_hopper ready: $(( $(date +%s) - T0 )) s"
# a fresh machine: the state an earlier session's calls returned, carried back in build/corn-carry
if ! [ -d build/corn ] && ls build/corn-carry/corn-state.tgz.* > /dev/null 2>&1; then
  cat build/corn-carry/corn-state.tgz.* | tar xzf - && echo "build/corn: unpacked from build/corn-carry ($(ls build/corn/*.stopped 2> /dev/null | wc -l) runs to continue)"
fi
nvidia-cuda-mps-control -d 2> /dev/null
stop=${1:-500}
stop=$(( stop - ($(date +%s) - T0) )); [ "$stop" -ge 30 ] || stop=30
# a checkpoint every 0.02 s of simulated time: ~1 400 steps, a few seconds past the stop
CORN_JOBS=${JOBS:-12} CORN_STOP_AFTER=$stop CORN_CHECKPOINT=${CORN_CHECKPOINT:-0.02} tools/corn_arching.sh build/cuda/study_hopper build/corn
status=$?
echo "corn_arching: status $status after $(( $(date +%s) - T0 )) s"
for f in build/corn/W*_s*.log; do echo "$f: $(grep -a "^pace:" "$f" | tail -1)"; done
tar czf "$out/corn.tgz" --exclude='*.vtu' --exclude='*.blz' --exclude='*.pvd' build/corn
# the state to continue from in a later session: a finished run's checkpoint is not needed
for c in build/corn/W*_s*/; do [ -e "${c%/}.stopped" ] || rm -f "$c/checkpoint.blz"; done
tar czf - --exclude='*.vtu' build/corn | split -b 15M -d - "$out/corn-state.tgz."
ls -la "$out"/corn-state.tgz.*
# what comes back is at most 64 MiB in 8 files (the device README), and what is carried back at
# most 64 MiB with the tree: a checkpoint of a settled run is ~10 MB (13 824 polyhedra in double
# with their contacts), so twelve may not fit; then run fewer at a time (CORN_SEEDS="1" JOBS=4)
state=$(cat "$out"/corn-state.tgz.* | wc -c)
[ "$state" -lt 40000000 ] || echo "corn: WARNING: the runs' state is $state bytes: it may not come back or be carried whole; run fewer at a time"
# no gnuplot there: the summary (corn.md) is written before the plot fails; CORN_RUN=0 redoes both here
[ -e build/corn/summary.csv ] && cp studies/hopper/corn.md build/corn/summary*.csv "$out/"
cp plots/fig-2.17.png "$out/" 2> /dev/null
echo quit | nvidia-cuda-mps-control
exit "$status"
