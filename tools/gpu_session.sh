#!/usr/bin/env bash
# For a GPU machine with nvcc but no package registry (such as the lent device machine): builds and
# runs the CUDA verification suite, the benchmark (default skin and no skin) and the default study,
# writing logs and result CSVs to the folder given (default /tmp/blaze-gpu).
# The tree may come without .git: pass BLAZE_COMMIT=<hash> so results name their commit.
# GSL (the suite's references) and toml++ (scene files) are not installed there:
# `../shared/tools/device-deps.sh libtomlplusplus-dev` puts their .debs in .devdeps/, which the
# device call carries; they are unpacked here.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/blaze-gpu}
mkdir -p "$out"
. tools/device_env.sh
n=$(nproc)
nvidia-smi -L
make test BACKEND=cuda NPROC="$n" > "$out/test.log" 2>&1
echo "make test BACKEND=cuda: rc=$?"
cp build/cuda/verification.tsv "$out/" 2>/dev/null
sed 's/\x1b\[[0-9;]*m//g' "$out/test.log" | grep -a "CPU vs GPU\|verification on\|test cases\|assertions\|error\|cube packing\|tumbling\|normal:\|polyhedron contact" | tail -20
make bench NPROC="$n" > "$out/bench.log" 2>&1
echo "make bench: rc=$?"
build/cuda/blaze_bench --out bench/results --skin 0 --max-n 1000000 > "$out/bench_skin0.log" 2>&1
echo "bench --skin 0: rc=$?"
make run NPROC="$n" > "$out/run.log" 2>&1
echo "make run: rc=$?"
grep -a "backend\|discharged .* of\|wall time" "$out/run.log"
cp bench/results/nvidia-*.csv "$out/" 2>/dev/null
tail -30 "$out/bench.log"
grep -a "N=" "$out/bench_skin0.log"
