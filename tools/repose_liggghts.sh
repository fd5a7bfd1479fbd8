#!/usr/bin/env bash
# The LIGGGHTS side of the repose study (make fig-repose-liggghts; studies/repose/main.cpp): the
# same pile in LIGGGHTS 3.8.0 (Debian package liggghts, installed through apt when missing and run
# as root), case by case, and its angle measured by Blaze's own function, side by side with
# Blaze's in data/repose/angles.csv.
#
#   tools/repose_liggghts.sh [--cores C] [--blaze PATH] [--dir DIR] [--keep] CASE... [-- --set key=value...]
#     CASE          mu_s:mu_r, e.g. 0.4:0.05
#     --cores C     LIGGGHTS MPI ranks [1]
#     --dir DIR     the sweep's folder, where Blaze's cases and angles.csv are [data/repose; the
#                   full size's: data/repose/full]
#     --blaze PATH  the study binary that exports and measures [build/cpu/study_repose]
#     after --       overrides given to the study (the size: make fig-repose-liggghts passes REPOSE_SIZE's)
#
# Per case: `study_repose --export-liggghts` writes walls.stl, gate.stl, beads.data and params.txt
# (the numbers of studies/repose/repose.toml with the overrides, 17 digits) into
# DIR/<case>/liggghts/; studies/repose/repose.liggghts.in is filled with them; LIGGGHTS
# runs there; `study_repose --measure final.dump` fits the angle and writes the LIGGGHTS columns.
set -euo pipefail
cd "$(dirname "$0")/.."
cores=1 blaze=build/cpu/study_repose keep=0 top=data/repose
cases=() sets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --cores) cores=$2; shift 2 ;;
    --blaze) blaze=$2; shift 2 ;;
    --dir) top=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    --) shift; sets=("$@"); break ;;
    -h|--help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) cases+=("$1"); shift ;;
  esac
done
[[ ${#cases[@]} -gt 0 ]] || { echo "repose_liggghts: give at least one case mu_s:mu_r" >&2; exit 2; }
[[ -x $blaze ]] || { echo "repose_liggghts: $blaze is not built (make $blaze)" >&2; exit 1; }
if ! command -v liggghts >/dev/null; then
  if [[ $(id -u) -eq 0 ]]; then
    apt-get install -y liggghts >/dev/null || { apt-get update >/dev/null && apt-get install -y liggghts >/dev/null; }
  else
    echo "repose_liggghts: LIGGGHTS is missing; as root run: apt-get install -y liggghts" >&2; exit 1
  fi
fi
run=(liggghts)
if [[ $cores -gt 1 ]] && command -v mpirun >/dev/null; then
  root=(); [[ $(id -u) -eq 0 ]] && root=(--allow-run-as-root)
  run=(mpirun "${root[@]}" -np "$cores" -x OMP_NUM_THREADS=1 liggghts)
fi

for c in "${cases[@]}"; do
  mus=${c%%:*} mur=${c##*:}
  dir=$top/mus${mus}_mur${mur}
  case_sets=("${sets[@]}" --set "pair[0].friction=$mus" --set "pair[1].friction=$mus"
             --set "pair[0].rolling_friction=$mur" --set "pair[1].rolling_friction=$mur" --set "output.directory=$dir")
  args=(); for s in "${case_sets[@]}"; do args+=("$s"); done
  "$blaze" studies/repose/repose.toml "${args[@]}" --export-liggghts "$dir/liggghts" >/dev/null
  subst=()
  while IFS='=' read -r k v; do subst+=(-e "s|@$k@|$v|g"); done <"$dir/liggghts/params.txt"
  # mu_r = 0: no rolling model (LIGGGHTS's epsd divides by its rolling stiffness, zero there).
  rolling="rolling_friction epsd"
  awk -v m="$mur" 'BEGIN { exit !(m + 0 == 0) }' && rolling=""
  subst+=(-e "s|@ROLLING@|$rolling|g")
  sed "${subst[@]}" studies/repose/repose.liggghts.in >"$dir/liggghts/in.repose"
  if grep -n '@[A-Z_]*@' "$dir/liggghts/in.repose"; then echo "repose_liggghts: a placeholder above has no value" >&2; exit 1; fi
  echo "repose_liggghts: mu_s = $mus, mu_r = $mur: ${run[*]} -in in.repose (in $dir/liggghts)"
  t0=$(date +%s.%N)
  (cd "$dir/liggghts" && "${run[@]}" -in in.repose -log log.liggghts >liggghts.out 2>&1) || {
    tail -20 "$dir/liggghts/liggghts.out" >&2; echo "repose_liggghts: LIGGGHTS failed ($dir/liggghts)" >&2; exit 1; }
  wall=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  "$blaze" studies/repose/repose.toml "${args[@]}" --measure "$dir/liggghts/final.dump" --wall-time "$wall"
  [[ $keep -eq 1 ]] || rm -f "$dir/liggghts/beads.data"
done
