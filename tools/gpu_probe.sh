#!/usr/bin/env bash
# One device call for lever measurements (issue 18): builds blaze and blaze_bench variants in
# parallel (-D flags per variant), then runs the history bench at 1e7 for each, the realistic
# blaze-run scene with --phases, and ncu on the history contact kernel. Output under $1.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/blaze-probe}; mkdir -p "$out"
if [ -d .devdeps ]; then
  mkdir -p /tmp/dd && for f in .devdeps/*.deb; do dpkg -x "$f" /tmp/dd; done
  export CPATH=/tmp/dd/usr/include${CPATH:+:$CPATH} LIBRARY_PATH=/tmp/dd/usr/lib/x86_64-linux-gnu${LIBRARY_PATH:+:$LIBRARY_PATH} \
         LD_LIBRARY_PATH=/tmp/dd/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
fi
export BLAZE_SKIP_DEPS=1
NV="nvcc -std=c++17 -O3 -arch=sm_90 -DEIGEN_NO_CUDA -Xcompiler -fopenmp -Iinclude -I. -isystem /usr/include/eigen3 -DBLAZE_TEST_HEADER_ONLY"
mkdir -p /tmp/pb
( make build/cuda/blaze -j8 > "$out/build_blaze.log" 2>&1; echo "blaze build rc=$?" ) &
for v in ${VARIANTS:-"base:"}; do
  name=${v%%:*}; flags=${v#*:}
  ( $NV ${flags//,/ } -x cu -c bench/bench.cpp -o /tmp/pb/$name.o && nvcc -arch=sm_90 -Xcompiler -fopenmp /tmp/pb/$name.o -o /tmp/pb/bench_$name; echo "bench $name rc=$?" ) &
done
wait
ls -la /tmp/pb build/cuda/blaze 2>&1 | tail -5
for v in ${VARIANTS:-"base:"}; do
  name=${v%%:*}
  echo "== bench $name"; /tmp/pb/bench_$name --cases ${BENCH_CASES:-history} --min-n ${BENCH_N:-10000000} --max-n ${BENCH_N:-10000000} --out /tmp/pb/res_$name 2>&1 | tail -6
  cat /tmp/pb/res_$name/*.csv >> "$out/bench.csv"
done > "$out/bench.log"
for s in ${SCENES:-}; do
  echo "== blaze run $s"; timeout 200 build/cuda/blaze run $s --quiet --phases 2>&1 | tail -6
  echo "== blaze run $s, no output"; timeout 200 build/cuda/blaze run $s --quiet --set output.csv_interval=0 --set output.vtu_interval=0 2>&1 | tail -3
done > "$out/run.log"
if [ -n "${NCU_KERNELS:-}" ] && command -v ncu >/dev/null; then
  first=${VARIANTS:-base:}; first=${first%%:*}; first=${first%% *}
  ncu --kernel-name-base demangled --kernel-name "regex:${NCU_KERNELS}" --launch-skip ${NCU_SKIP:-30} --launch-count ${NCU_COUNT:-2} \
      --section SpeedOfLight --section Occupancy --section WarpStateStats --section MemoryWorkloadAnalysis --section LaunchStats \
      /tmp/pb/bench_$first --cases history --min-n 1000000 --max-n 1000000 --out /tmp/pb/ncu > "$out/ncu.txt" 2>&1
  echo "ncu rc=$?"
fi
