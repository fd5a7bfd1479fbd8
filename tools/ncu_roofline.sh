#!/usr/bin/env bash
# Roofline positions of the hottest kernels (bench/README.md): Nsight Compute measures one launch
# of each after the warm-up, with the DRAM bytes, FP32/FP64 instruction counts (FLOP = add + mul
# + 2 fma) and time; tools/ncu_roofline.py turns them into achieved GB/s, GFLOP/s and FLOP/byte.
# Usage (on a GPU machine): tools/ncu_roofline.sh BENCH_BINARY OUT_DIR [CASE ...] (default: all cases)
set -euo pipefail
bench=${1:?bench binary}
out=${2:?output folder}
shift 2
only=" $* "
mkdir -p "$out"
metrics=gpu__time_duration.sum,dram__bytes.sum,lts__t_bytes.sum,launch__registers_per_thread
metrics+=,smsp__sass_thread_inst_executed_op_fadd_pred_on.sum,smsp__sass_thread_inst_executed_op_fmul_pred_on.sum
metrics+=,smsp__sass_thread_inst_executed_op_ffma_pred_on.sum,smsp__sass_thread_inst_executed_op_dadd_pred_on.sum
metrics+=,smsp__sass_thread_inst_executed_op_dmul_pred_on.sum,smsp__sass_thread_inst_executed_op_dfma_pred_on.sum
metrics+=,sm__throughput.avg.pct_of_peak_sustained_elapsed,sm__warps_active.avg.pct_of_peak_sustained_active
metrics+=,smsp__inst_executed.sum,smsp__issue_active.avg.pct_of_peak_sustained_active
profile() {  # name, kernel regex, launches to skip, launches to profile, bench arguments...
  local name=$1 regex=$2 skip=$3 count=$4
  shift 4
  [ "$only" = "  " ] || [[ "$only" == *" $name "* ]] || return 0
  timeout 300 ncu --csv --page raw --metrics "$metrics" --kernel-name-base demangled --kernel-name "regex:$regex" \
    --launch-skip "$skip" --launch-count "$count" "$bench" --out /tmp/ncu-bench "$@" > "$out/ncu-$name.csv" 2> "$out/ncu-$name.log" || true
}
# Spheres, 1e7, linear float: the contact kernel and the two integration half-steps (step ~150).
profile spheres-1e7 'ContactForces|Integrate' 450 3 --cases spheres --min-n 10000000 --max-n 10000000
# Packed cubes and dodecahedra, 1e6, each pair from both sides (the cube case runs first: 95
# contact launches, 20 warm-up + 60 timed + 15 per-phase steps) ...
profile cubes-packed-1e6 'ContactForces' 40 1 --cases packed --min-n 1000000 --max-n 1000000 --pairs both_sides
profile dodecahedra-packed-1e6 'ContactForces' 140 1 --cases packed --min-n 1000000 --max-n 1000000 --pairs both_sides
# ... and once (the default for polyhedra): the pair kernel and the gather of the same step (the
# regex matches both, so 190 launches per case).
profile cubes-packed-1e6-once 'PairForces' 80 2 --cases packed --min-n 1000000 --max-n 1000000 --pairs once
profile dodecahedra-packed-1e6-once 'PairForces' 270 2 --cases packed --min-n 1000000 --max-n 1000000 --pairs once
