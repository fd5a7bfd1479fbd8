#!/usr/bin/env bash
# The full-size repose piles (make fig-repose REPOSE_SIZE=full) on the lent GPU machine, where a
# call lasts at most 10 minutes and at most 8 files come back: builds study_repose for CUDA (kept
# between calls on a warm machine), then runs the cases one after another while the call has time
# for one more, and after each packs data/repose/full (profiles, manifests, angles.csv, logs; not
# the VTU frames) into OUT/repose_full.tar.gz. A second call runs the cases the first left.
# Usage: tools/repose_device.sh OUT DEADLINE_S MU_S:MU_R...
#   REPOSE_CASE_S (default 150): the seconds a case is given; none starts with fewer left.
set -uo pipefail
cd "$(dirname "$0")/.."
out=$1 deadline=$2
shift 2
. tools/device_env.sh
make -j"$(nproc)" build/cuda/study_repose > "$out/build_repose.log" 2>&1 || { tail -40 "$out/build_repose.log"; exit 1; }
echo "study_repose built at ${SECONDS} s"
dir=data/repose/full
mkdir -p "$dir"
status=0
for c in "$@"; do
  left=$((deadline - SECONDS))
  if [ "$left" -lt "${REPOSE_CASE_S:-150}" ]; then
    echo "repose $c: not started (${left} s left)"
    continue
  fi
  t0=$SECONDS
  tools/repose_sweep.sh build/cuda/study_repose "$dir" 1 "${c%%:*}" "${c##*:}" || status=1
  echo "  ($((SECONDS - t0)) s)"
  tar -czf "$out/repose_full.tar.gz" --exclude='*.vtu' "$dir"
done
exit $status
