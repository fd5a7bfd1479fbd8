#!/usr/bin/env bash
# On the lent GPU machine (no package registry there): unpacks .devdeps (GSL and toml++ .debs made
# by ../shared/tools/device-deps.sh libtomlplusplus-dev), builds the CUDA test binary from the test
# sources given (all when none: build/cuda/blaze_tests; some: build-sub/cuda/blaze_tests) and runs
# the named suites, writing the report rows to $OUT (or /tmp/blaze-gpu) as verification.tsv.
#   tools/gpu_suites.sh "feeding checkpoint" [verification/test_feeding.cpp ...]
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-/tmp/blaze-gpu}
mkdir -p "$out"
. tools/device_env.sh
suites=$1
shift
if [ $# -gt 0 ]; then
  build=build-sub
  make -j"$(nproc)" BUILD=$build TEST_SRC="verification/test_main.cpp $*" $build/cuda/blaze_tests > "$out/build_tests.log" 2>&1 || { tail -30 "$out/build_tests.log"; exit 1; }
else
  build=build
  make -j"$(nproc)" $build/cuda/blaze_tests > "$out/build_tests.log" 2>&1 || { tail -30 "$out/build_tests.log"; exit 1; }
fi
rc=0
for s in $suites; do
  BLAZE_REPORT="$out/verification.tsv" $build/cuda/blaze_tests --run_test="$s" --log_level=message --report_level=short --color_output=no \
    > "$out/suite_$s.log" 2>&1
  r=$?
  echo "suite $s: rc=$r $(grep -a 'assertions\|test cases' "$out/suite_$s.log" | tr '\n' ' ')"
  [ $r -ne 0 ] && { rc=$r; grep -a "error" "$out/suite_$s.log" | head -10; }
done
exit $rc
