#!/usr/bin/env bash
# make bench-compare: Blaze's CPU backend against LIGGGHTS 3.8.0 on one scene, one contact law
# and the same cores, in one run (bench/compare/README.md says what is compared and where the
# two codes still differ).
#
#   tools/bench_compare.sh [options]
#     --side N        bcc block of N^3 + (N-1)^3 spheres [37: 97 309]
#     --particles N   the bcc block nearest to N spheres (instead of --side)
#     --steps S       timed steps [600]
#     --warmup W      untimed settling steps before them [15 x side]
#     --cores C       LIGGGHTS MPI ranks = Blaze OpenMP threads [2]
#     --law L         linear (spring-dashpot, history-free friction) or hertz-history (Hertz with
#                     the Mindlin tangential spring: LIGGGHTS hertz/history) [linear]
#     --blaze PATH    the Blaze binary [build/cpu/blaze]
#     --record        append a row to bench/results/compare-cpu.csv (compare-cpu-LAW.csv for other laws)
#     --keep          keep the generated inputs and logs (their folder is printed)
#
# Both codes start from the same touching bcc block, settle for W untimed steps and are timed
# over the next S steps: LIGGGHTS by its own "Loop time" of the second run, Blaze by the
# "wall time ... particle-steps/s" line of a run restarted from the warm-up's checkpoint (or,
# from a binary that does not print it, the wall clock of that process). Prints
# particle-steps/s of each and their ratio. Installs LIGGGHTS (apt) when run as root.
set -euo pipefail

cd "$(dirname "$0")/.."
root=$(pwd)

usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; }

side=37           # bcc: side^3 + (side-1)^3 spheres; 37 -> 97 309
steps=600         # timed steps
warmup=auto       # untimed settling steps; auto = 15 x side (the load reaches the top layer at ~12 x side)
cores=2           # LIGGGHTS MPI ranks = Blaze OpenMP threads
blaze=build/cpu/blaze
law=linear
record=0
keep=0

# fail MESSAGE: stop, keeping the generated inputs and logs for a look.
fail() {
  echo "bench_compare: $*" >&2
  if [[ -n ${tmp:-} ]]; then
    trap - EXIT
    echo "bench_compare: inputs and logs are in $tmp" >&2
  fi
  exit 1
}
positive() { [[ "$2" =~ ^[0-9]+$ && "$2" -ge "$3" ]] || { echo "bench_compare: $1 must be an integer >= $3, got '$2'" >&2; exit 2; }; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --side) positive --side "${2-}" 2; side=$2; shift 2 ;;
    --particles)
      positive --particles "${2-}" 9
      # the bcc block whose count is nearest
      side=$(awk -v n="$2" 'BEGIN { best = 2; for (s = 2; s < 2000; ++s) { c = s^3 + (s-1)^3; d = c > n ? c - n : n - c;
                                    if (s == 2 || d < bd) { bd = d; best = s } } print best }')
      shift 2 ;;
    --steps) positive --steps "${2-}" 1; steps=$2; shift 2 ;;
    --warmup) positive --warmup "${2-}" 0; warmup=$2; shift 2 ;;
    --cores) positive --cores "${2-}" 1; cores=$2; shift 2 ;;
    --law) [[ ${2-} == linear || ${2-} == hertz-history ]] || { echo "bench_compare: --law must be linear or hertz-history, got '${2-}'" >&2; exit 2; }
      law=$2; shift 2 ;;
    --blaze) [[ -n ${2-} ]] || { echo "bench_compare: --blaze needs a path" >&2; exit 2; }; blaze=$2; shift 2 ;;
    --record) record=1; shift ;;
    --keep) keep=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "bench_compare: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ $warmup == auto ]] && warmup=$((15 * side))

# ---- the tools ----------------------------------------------------------------------------------
[[ -x $blaze ]] || fail "$blaze is not built (make $blaze)"
if ! command -v liggghts >/dev/null; then
  if [[ $(id -u) -eq 0 ]]; then
    echo "bench_compare: installing LIGGGHTS (Debian package liggghts)"
    apt-get install -y liggghts >/dev/null || { apt-get update >/dev/null && apt-get install -y liggghts >/dev/null; }
  else
    fail "LIGGGHTS is missing; as root run: apt-get install -y liggghts"
  fi
fi
liggghts_cmd=(liggghts)
liggghts_how="$cores MPI ranks"
if command -v mpirun >/dev/null; then
  mpi_root=(); [[ $(id -u) -eq 0 ]] && mpi_root=(--allow-run-as-root)
  liggghts_cmd=(mpirun "${mpi_root[@]}" -np "$cores" -x OMP_NUM_THREADS=1 liggghts)
else
  # The Debian build has no OpenMP package: one rank uses one core.
  echo "bench_compare: no mpirun (Debian package openmpi-bin): LIGGGHTS runs as 1 rank on 1 core" >&2
  liggghts_how="1 MPI rank (no mpirun)"
fi

# ---- the scene: every number both inputs get ---------------------------------------------------
radius=1e-3 density=2500 stiffness=1e4 restitution=0.5 friction=0.4 kt=0.05 skin_over_r=0.2
# hertz-history: a soft glass (Rayleigh time 2.7e-5 s: the linear scene's dt is 0.1 of it)
young=1e8 poisson=0.3
# awk prints %.17g, so both codes parse the same doubles.
eval "$(awk -v r=$radius -v rho=$density -v k=$stiffness -v e=$restitution -v n=$side -v skin=$skin_over_r \
            -v warm=$warmup -v steps=$steps 'BEGIN {
  pi = atan2(0, -1); m = rho * 4 / 3 * pi * r^3
  dt = pi * sqrt(0.5 * m / k) / 25                  # t_c / 25, t_c = pi sqrt(m*/k), m* = m/2
  le = log(e); beta = -2 * le / sqrt(le * le + pi * pi)
  a = 4 * r / sqrt(3); top = (n - 1) * a            # bcc cube edge: touching along the body diagonal
  printf "dt=%.17g a=%.17g half_a=%.17g\n", dt, a, a / 2
  printf "cn_pp=%.17g cn_pw=%.17g\n", beta * sqrt(k * m / 2), beta * sqrt(k * m)
  printf "w0=%.17g w1=%.17g lo=%.17g hi_x=%.17g hi_y=%.17g\n", -r, top + r, -2 * r, top + 2 * r, top + 5 * r
  printf "skin=%.17g diameter=%.17g side_hi=%.17g\n", skin * r, 2 * r, n - 0.75
  printf "t_warm=%.17g t_end=%.17g\n", warm * dt, (warm + steps) * dt
  printf "particles=%d\n", n^3 + (n - 1)^3 }')"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/bench-compare.XXXXXX")
if [[ $keep -eq 1 ]]; then echo "bench_compare: inputs and logs kept in $tmp"; else trap 'rm -rf "$tmp"' EXIT; fi

subst=(-e "s|@RADIUS@|$radius|g" -e "s|@DIAMETER@|$diameter|g" -e "s|@DENSITY@|$density|g"
       -e "s|@YOUNG@|$young|g" -e "s|@POISSON@|$poisson|g" -e "s|@K@|$stiffness|g" -e "s|@E@|$restitution|g" -e "s|@MU@|$friction|g" -e "s|@KT@|$kt|g"
       -e "s|@CN_PP@|$cn_pp|g" -e "s|@CN_PW@|$cn_pw|g" -e "s|@DT@|$dt|g"
       -e "s|@SKIN_OVER_R@|$skin_over_r|g" -e "s|@SKIN@|$skin|g"
       -e "s|@LO@|$lo|g" -e "s|@HI_X@|$hi_x|g" -e "s|@HI_Y@|$hi_y|g" -e "s|@W0@|$w0|g" -e "s|@W1@|$w1|g"
       -e "s|@TOP@|$hi_y|g" -e "s|@A@|$a|g" -e "s|@HALF_A@|$half_a|g" -e "s|@SIDE@|$side|g"
       -e "s|@SIDE_B@|$((side - 1))|g" -e "s|@SIDE_HI@|$side_hi|g"
       -e "s|@WARMUP@|$warmup|g" -e "s|@STEPS@|$steps|g" -e "s|@THERMO@|5000|g"
       -e "s|@END_TIME@|$t_warm|g" -e "s|@CHECKPOINT@|$t_warm|g" -e "s|@DIR@|$tmp/blaze|g")
template=packing; [[ $law == hertz-history ]] && template=packing-hertz
sed "${subst[@]}" "bench/compare/$template.liggghts.in" >"$tmp/packing.liggghts"
sed "${subst[@]}" "bench/compare/$template.toml.in" >"$tmp/packing.toml"
! grep -n '@[A-Z_]*@' "$tmp/packing.liggghts" "$tmp/packing.toml" || fail "a placeholder above has no value"

cpu=$(awk -F': ' '/^model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null || true)
echo "bench_compare: $law law, $particles spheres (bcc, side $side), $warmup warm-up + $steps timed steps, dt = $dt s," \
     "$cores cores of ${cpu:-an unknown CPU}"
# Cores kept busy by other work over one second (from /proc/stat), before anything runs.
cpu_ticks() { awk '/^cpu / { print $2 + $3 + $4 + $7 + $8 + $9, $2 + $3 + $4 + $5 + $6 + $7 + $8 + $9 }' /proc/stat; }
read -r busy0 all0 < <(cpu_ticks)
sleep 1
read -r busy1 all1 < <(cpu_ticks)
busy=$(awk -v b="$((busy1 - busy0))" -v a="$((all1 - all0))" -v n="$(nproc)" 'BEGIN { printf "%.2f", (a > 0 ? n * b / a : 0) }')
if awk -v b="$busy" 'BEGIN { exit !(b > 0.2) }'; then
  # Two OpenMP (or MPI) programs on the same cores make every barrier wait for a time slice:
  # Blaze's rate can fall tenfold, LIGGGHTS's less, so the ratio means little then.
  echo "bench_compare: WARNING: other work kept $busy cores busy just before the runs: the rates" \
       "below are not comparable (the CSV row records it)"
fi

# ---- LIGGGHTS --------------------------------------------------------------------------------------
echo "bench_compare: LIGGGHTS, $liggghts_how: ${liggghts_cmd[*]} -in packing.liggghts"
(cd "$tmp" && "${liggghts_cmd[@]}" -in packing.liggghts -log log.liggghts >liggghts.out 2>&1) || {
  tail -20 "$tmp/liggghts.out" >&2
  fail "LIGGGHTS failed"
}
# "Loop time of 12.3 on 2 procs for 500 steps with 97309 atoms": the last one is the timed run.
read -r l_time l_procs l_steps l_atoms < <(awk '/^Loop time of/ { t = $4; p = $6; s = $9; n = $12 }
                                                 END { print t, p, s, n }' "$tmp/liggghts.out")
[[ -n ${l_time:-} && $l_steps == "$steps" ]] || fail "no 'Loop time' line for the $steps timed steps in liggghts.out"
[[ $l_atoms == "$particles" ]] || fail "LIGGGHTS kept $l_atoms of $particles atoms"
l_rate=$(awk -v n="$l_atoms" -v s="$l_steps" -v t="$l_time" 'BEGIN { printf "%.4g", n * s / t }')

# ---- Blaze ---------------------------------------------------------------------------------------
export OMP_NUM_THREADS=$cores
blaze_run() {  # blaze_run LOG ARGS...: one blaze process, its wall clock in $b_clock
  local log=$1 t0 t1
  shift
  t0=$(date +%s.%N)
  "$blaze" run "$tmp/packing.toml" --quiet "$@" >"$log" 2>&1 || {
    cat "$log" >&2
    fail "blaze failed"
  }
  t1=$(date +%s.%N)
  b_clock=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.6f", b - a }')
}
echo "bench_compare: Blaze, $cores OpenMP threads: $blaze run packing.toml --quiet"
timed_args=(--set "end_time=$t_end" --set checkpoint_interval=0)
if [[ $warmup -gt 0 ]]; then
  blaze_run "$tmp/blaze-warmup.out"
  timed_args+=(--restart "$tmp/blaze/checkpoint.blz")
fi
blaze_run "$tmp/blaze.out" "${timed_args[@]}"
# "done: 900 steps, 97309 particles left, 0 removed (left the domain); ..."
read -r b_left b_removed < <(awk '/^done:/ { l = $4; r = $7 } END { print l " " r }' "$tmp/blaze.out")
if [[ ${b_left:-} != "$particles" || ${b_removed:-} != 0 ]]; then
  cat "$tmp/blaze.out" >&2
  fail "Blaze kept ${b_left:-?} of $particles particles (${b_removed:-?} removed)"
fi
# "wall time 12.3 s for the steps and output, 3.1e+06 particle-steps/s" (the loop only); a binary
# without that line is timed by the process's wall clock (+ start-up and checkpoint reading).
b_rate=$(awk '/^wall time .* particle-steps\/s/ { r = $(NF-1) } END { print r }' "$tmp/blaze.out")
if [[ -n $b_rate ]]; then
  b_time=$(awk '/^wall time/ { print $3 }' "$tmp/blaze.out")
  b_source="printed by blaze (loop only)"
else
  b_time=$b_clock
  b_rate=$(awk -v n="$particles" -v s="$steps" -v t="$b_clock" 'BEGIN { printf "%.4g", n * s / t }')
  b_source="process wall clock (includes start-up)"
fi
ratio=$(awk -v b="$b_rate" -v l="$l_rate" 'BEGIN { printf "%.3f", b / l }')

# ---- report --------------------------------------------------------------------------------------
printf '\n%-10s %10s %8s %12s %24s  %s\n' code particles steps "time (s)" "particle-steps/s" "timing"
printf '%-10s %10s %8s %12s %24s  %s\n' Blaze "$particles" "$steps" "$b_time" "$b_rate" "$b_source"
printf '%-10s %10s %8s %12s %24s  %s\n' LIGGGHTS "$l_atoms" "$l_steps" "$l_time" "$l_rate" "Loop time, $l_procs procs"
printf '\nBlaze / LIGGGHTS = %s\n' "$ratio"

if [[ $record -eq 1 ]]; then
  csv=bench/results/compare-cpu.csv; [[ $law == linear ]] || csv=bench/results/compare-cpu-$law.csv
  commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
  git diff --quiet HEAD 2>/dev/null || commit="$commit+dirty"
  [[ -f $csv ]] || echo "date,commit,cpu,cores,N,steps,warmup,dt_s,blaze_particle_steps_per_s,liggghts_particle_steps_per_s,ratio,blaze_timing,liggghts_procs,busy_cores_before" >"$csv"
  printf '%s,%s,"%s",%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n' "$(date -u +%Y-%m-%dT%H:%M:%SZ)" "$commit" "${cpu//\"/}" "$cores" \
    "$particles" "$steps" "$warmup" "$dt" "$b_rate" "$l_rate" "$ratio" \
    "$([[ $b_source == printed* ]] && echo loop || echo process)" "$l_procs" "$busy" >>"$csv"
  echo "bench_compare: appended a row to $root/$csv"
fi
