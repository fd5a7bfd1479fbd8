#!/usr/bin/env bash
# make fig-repose's sweep: study_repose for every (mu_s, mu_r), JOBS at a time (on CPU cores; not
# on one GPU: processes sharing it without MPS run slower in total, Makefile), each case in
# DIR/mus<mu_s>_mur<mu_r>/ with its log beside it, the angles in DIR/angles.csv (the study locks
# it while it writes its row). Exit status: the first failing case's (2, "not at rest by
# end_time", counts as done).
# Usage: tools/repose_sweep.sh STUDY_BINARY DIR JOBS "MU_S..." "MU_R..." [-- --set key=value ...]
set -uo pipefail
cd "$(dirname "$0")/.."
bin=$1 dir=$2 jobs=$3 mus_list=$4 mur_list=$5
shift 5
[ "${1:-}" = "--" ] && shift
mkdir -p "$dir"
status=0
run_case() {
  local mus=$1 mur=$2 case_dir="$dir/mus$1_mur$2"
  shift 2
  "$bin" studies/repose/repose.toml "$@" --set "pair[0].friction=$mus" --set "pair[1].friction=$mus" \
    --set "pair[0].rolling_friction=$mur" --set "pair[1].rolling_friction=$mur" \
    --set "output.directory=$case_dir" > "$case_dir.log" 2>&1
}
pids=()
for mus in $mus_list; do
  for mur in $mur_list; do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
    ( run_case "$mus" "$mur" "$@"; rc=$?; echo "repose mu_s = $mus, mu_r = $mur: exit $rc, $(grep -a 'angle of repose\|stopped at' "$dir/mus${mus}_mur${mur}.log" | tr '\n' ' ')"
      [ $rc -eq 0 ] || [ $rc -eq 2 ] ) &
    pids+=($!)
  done
done
for p in "${pids[@]}"; do wait "$p" || status=1; done
exit $status
