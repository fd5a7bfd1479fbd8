#!/usr/bin/env bash
# make bench-run: what a `blaze run` user gets on a realistic scene against blaze_bench's dense bed
# of the same size (issue 18). Runs the scene (default bench/scenes/lattice_fall_1m.toml, 1,048,576
# spheres falling into a packing, linear law, float) through `blaze run` three times: with its output
# (a time-series row every 10 ms, a VTU frame every 0.1 s), then with no output, then with --phases
# (per-phase times; that run's rate is not recorded: timing each phase costs synchronisations); runs
# blaze_bench's spheres case at 1e6; writes one CSV row per run to
# bench/results/<device>-<date>-bench-run.csv:
#   device, commit, date, scene, particles, run_particle_steps_per_s (wall, output included),
#   run_steps_only (wall less the output's time), run_no_output, bench_dense_1e6 (linear, float; BENCH_N other than 1e6 only to try the script),
#   ratio = bench_dense_1e6 / run_particle_steps_per_s (the issue's goal: <= 1.3)
# Usage: tools/bench_run.sh <build/backend dir> [scene]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:?usage: tools/bench_run.sh build/<backend> [scene]}
scene=${2:-bench/scenes/lattice_fall_1m.toml}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin/blaze" run "$scene" --quiet | tee "$tmp/with.log"
"$bin/blaze" run "$scene" --quiet --set output.csv_interval=0 --set output.vtu_interval=0 | tee "$tmp/without.log"
# where the time goes, phase by phase (each phase then waits for the last: slower, not counted)
"$bin/blaze" run "$scene" --quiet --phases | grep -a "phases\|neighbour-list builds"
n=${BENCH_N:-1000000}  # the bed's size (a smaller one only to try the script on a CPU)
"$bin/blaze_bench" --cases spheres --min-n "$n" --max-n "$n" --out "$tmp/bench" | tail -3
rate() { sed -n 's/.*wall time [0-9.]* s for the steps and output, \([0-9.e+-]*\) particle-steps\/s.*/\1/p' "$1"; }
steps_rate() { sed -n 's/.*steps [0-9.]* s (\([0-9.e+-]*\) particle-steps\/s).*/\1/p' "$1"; }
with=$(rate "$tmp/with.log"); steps=$(steps_rate "$tmp/with.log"); without=$(rate "$tmp/without.log")
particles=$(sed -n 's/.*steps, \([0-9]*\) particles left.*/\1/p' "$tmp/with.log")
csv=$(ls "$tmp"/bench/*.csv | head -1)
# the dense bed, linear law, float, N = 1e6 (columns by name: the bench's header)
bench=$(python3 - "$csv" "$n" <<'PY'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    if r["scene"] == "dense-bed" and r["law"] == "linear" and r["precision"] == "float" and r["N"] == sys.argv[2]:
        print(r["particle_steps_per_s"]); break
PY
)
device=$(python3 - "$csv" <<'PY'
import csv, sys
r = next(csv.DictReader(open(sys.argv[1])))
print(r["device"])
PY
)
commit=${BLAZE_COMMIT:-$(git rev-parse HEAD 2>/dev/null || echo unknown)}
date=$(date -u +%Y-%m-%dT%H:%M:%SZ)
slug=$(echo "$device" | sed 's/ (.*//' | tr 'A-Z ' 'a-z-')
out=bench/results/$slug-$(date -u +%Y-%m-%d)-bench-run.csv
[ -s "$out" ] || echo "device,commit,date,scene,particles,run_particle_steps_per_s,run_steps_only,run_no_output,bench_dense_1e6,ratio" > "$out"
ratio=$(python3 -c "print(f'{float(\"$bench\") / float(\"$with\"):.3f}')")
echo "\"$device\",$commit,$date,$scene,$particles,$with,$steps,$without,$bench,$ratio" >> "$out"
echo "bench-run: blaze run $with particle-steps/s with output ($steps stepping, $without without output), blaze_bench dense bed 1e6 $bench: ratio $ratio; row in $out"
