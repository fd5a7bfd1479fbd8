#!/usr/bin/env bash
# make fig-2.17: corn kernels arching in a hopper (thesis Figures 2.17-2.18; studies/hopper/corn.toml).
# For each orifice side W in CORN_ORIFICES (mm; default "22 27 33 44": 2, 2.5, 3 and 4 kernel
# lengths of 11 mm) and each seed in CORN_SEEDS (default "1 2 3"), the hopper is written as an STL
# (studies/hopper/make_hopper_stl.py), 13 824 kernels are poured in, settle behind the gate and are
# discharged; a run whose flow stops for [study] arch_time with kernels over the orifice has arched.
# Writes DIR/W<mm>_s<seed>/ (each run's output), DIR/summary.csv, studies/hopper/corn.md (per orifice:
# the runs that arched, when, and the mass that left before) and plots/fig-2.17.png.
# A GPU target (13 824 polyhedra, 2.4e5 steps a run; the twelve side by side under MPS: ~20 min of an H100).
# Usage: tools/corn_arching.sh STUDY_BINARY [DIR]           (DIR defaults to data/hopper/corn)
#   CORN_SET="feed[0].count=600 ..." adds --set overrides to every run (small trial runs);
#   CORN_RUN=0 only summarises the runs already in DIR.
#   CORN_JOBS=N runs N cases at once (default 1; on one GPU a few small runs share it well, more
#   so under MPS: `nvidia-cuda-mps-control -d`).
#   CORN_STOP_AFTER=S stops each run after S seconds of wall time at its next checkpoint (every
#   CORN_CHECKPOINT s of simulated time, default 0.1; study_hopper --stop-after) and leaves
#   DIR/W<mm>_s<seed>.stopped; the same command again continues the stopped runs from their
#   checkpoints (bitwise the run that never stopped), skips the finished ones, and summarises once
#   none is left stopped (for sessions shorter than the study).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$1 dir=${2:-data/hopper/corn}
orifices=${CORN_ORIFICES:-22 27 33 44}
seeds=${CORN_SEEDS:-1 2 3}
length=11                 # mm, a kernel's length (data/shapes/corn.shape)
mkdir -p "$dir"
sets=()
for s in ${CORN_SET:-}; do sets+=(--set "$s"); done
for w in $orifices; do
  python3 -c "import sys; w = float('$w'); sys.exit(0 if 8 <= w <= 120 else 1)" 2>/dev/null \
    || { echo "corn: CORN_ORIFICES: '$w' is not an orifice side from 8 to 120 mm"; exit 1; }
done
cases=""
for w in $orifices; do
  stl="$dir/W$w/hopper.stl"
  read -r half gate < <(python3 -c "w = $w / 1000; print(w / 2, w / 2 + 0.01)")
  if [ "${CORN_RUN:-1}" = 1 ]; then
    mkdir -p "$dir/W$w"
    python3 studies/hopper/make_hopper_stl.py --width 0.16 --height 0.3 --angle 60 --orifice "$(python3 -c "print($w / 1000)")" \
      --out "$stl" > /dev/null
  fi
  for seed in $seeds; do
    case_dir="$dir/W${w}_s$seed"
    cases="$cases $case_dir"
    [ "${CORN_RUN:-1}" = 1 ] || continue
    mkdir -p "$case_dir"
    rm -f "$case_dir.failed"
    stop=() restart=() fresh=1
    if [ -n "${CORN_STOP_AFTER:-}" ]; then
      stop=(--stop-after "$CORN_STOP_AFTER" --set "output.checkpoint_interval=${CORN_CHECKPOINT:-0.1}")
      if [ -e "$case_dir.stopped" ]; then restart=(--restart "$case_dir/checkpoint.blz"); fresh=0
      elif [ -e "$case_dir/manifest.txt" ]; then echo "corn: W = $w mm seed $seed: done before"; continue; fi
    fi
    while [ "$(jobs -rp | wc -l)" -ge "${CORN_JOBS:-1}" ]; do wait -n || true; done
    (
      [ "$fresh" = 0 ] || : > "$case_dir.log"
      status=0
      "$bin" studies/hopper/corn.toml --no-plot --set "mesh[0].file=\"$stl\"" --set "study.orifice_half_width=$half" \
        --set "wall[0].vertices=[[-$gate, -0.0005, $gate], [$gate, -0.0005, $gate], [$gate, -0.0005, -$gate], [-$gate, -0.0005, -$gate]]" \
        --set "simulation.seed=$seed" --set "output.directory=\"$case_dir\"" "${sets[@]}" "${stop[@]}" "${restart[@]}" >> "$case_dir.log" 2>&1 \
        || status=$?
      rm -f "$case_dir.stopped"
      if [ "$status" = 3 ]; then touch "$case_dir.stopped"; echo "corn: W = $w mm seed $seed: $(grep -a "^stopped at" "$case_dir.log" | tail -1 | cut -d: -f1)"; exit 0; fi
      [ "$status" = 0 ] || { echo "corn: W = $w mm seed $seed failed (see $case_dir.log)"; tail -5 "$case_dir.log"; touch "$case_dir.failed"; exit 1; }
      echo "corn: W = $w mm seed $seed: $(grep -a "^arched\|^no arch" "$case_dir.log" | tail -1)"
    ) &
  done
done
wait || true
for c in $cases; do
  [ -e "$c.failed" ] && { rm -f "$c.failed"; echo "corn: a run failed: not summarised"; exit 1; }
done
for c in $cases; do
  [ -e "$c.stopped" ] && { echo "corn: runs stopped at CORN_STOP_AFTER: run the same command again to continue them"; exit 3; }
done
python3 - "$length" "$dir/summary.csv" studies/hopper/corn.md $cases <<'PY'
import os, re, statistics, sys
length, summary, md, cases = float(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]
rows = []
for c in cases:
    m = {}
    path = os.path.join(c, "manifest.txt")
    if not os.path.exists(path):
        print(f"corn: no {path}: left out")
        continue
    for line in open(path):
        if " = " in line:
            k, v = line.rstrip("\n").split(" = ", 1)
            m[k.strip()] = v.strip()
    w, seed = re.search(r"W([0-9.]+)_s([0-9]+)$", c.rstrip("/")).groups()
    n, out = int(m["particles_at_opening"]), int(m["discharged_count"])
    rows.append(dict(w=float(w), seed=int(seed), particles=n, discharged=out, arched=m.get("arched", "no"),
                     last_exit=float(m.get("last_exit_s", "nan")), flow=float(m["flow_rate_kg_s"]), wall=float(m["wall_time_s"]),
                     device=m.get("device", "?"), commit=m.get("commit", "?")))
with open(summary, "w") as f:
    f.write("orifice_mm,w_over_length,seed,particles,discharged,arched,last_exit_s,flow_rate_kg_s,wall_time_s\n")
    for r in rows:
        f.write(f"{r['w']:g},{r['w']/length:.3f},{r['seed']},{r['particles']},{r['discharged']},{r['arched']},{r['last_exit']:.3f},"
                f"{r['flow']:.5f},{r['wall']:.1f}\n")
widths = sorted({r["w"] for r in rows})
with open(summary.replace(".csv", "_by_orifice.csv"), "w") as f:
    f.write("orifice_mm,w_over_length,runs,arched,arching_fraction,mean_discharged_fraction\n")
    for w in widths:
        rs = [r for r in rows if r["w"] == w]
        arched = sum(r["arched"] == "yes" for r in rs)
        f.write(f"{w:g},{w/length:.3f},{len(rs)},{arched},{arched/len(rs):.3f},"
                f"{statistics.mean(r['discharged']/max(r['particles'],1) for r in rs):.4f}\n")
with open(md, "w") as f:
    f.write("<!-- generated by `make fig-2.17` (tools/corn_arching.sh); do not edit -->\n")
    f.write("# Corn kernels arching in a hopper (thesis Figures 2.17-2.18)\n\n")
    f.write("13 824 corn-shaped polyhedra (11 x 8 x 4 mm) poured into a 16 cm square hopper with walls at 60 degrees converging\n"
            "to a square orifice of side W (studies/hopper/corn.toml, make_hopper_stl.py), settled, and discharged; Hertz-Mindlin,\n"
            "mu_pp 0.35, mu_wall 0.30. A run has arched when no kernel left for [study] arch_time with kernels over the orifice.\n"
            f"Runs: {len(rows)}; device: {', '.join(sorted({r['device'] for r in rows}))}; commit {', '.join(sorted({r['commit'] for r in rows}))}.\n\n")
    f.write("| W (mm) | W / kernel length | seed | kernels | discharged | arched | flow stopped at (s) | flow rate (kg/s) | wall time (s) |\n")
    f.write("|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        stop = f"{r['last_exit']:.2f}" if r["arched"] == "yes" else "-"
        f.write(f"| {r['w']:g} | {r['w']/length:.2f} | {r['seed']} | {r['particles']} | {r['discharged']} | {r['arched']} | {stop} | "
                f"{r['flow']:.4f} | {r['wall']:.0f} |\n")
    f.write("\n## Arching against the orifice\n\n| W (mm) | W / kernel length | runs arched | mean share discharged |\n|---|---|---|---|\n")
    for w in widths:
        rs = [r for r in rows if r["w"] == w]
        arched = sum(r["arched"] == "yes" for r in rs)
        f.write(f"| {w:g} | {w/length:.2f} | {arched} of {len(rs)} | {100*statistics.mean(r['discharged']/max(r['particles'],1) for r in rs):.1f}% |\n")
    fractions = [sum(r["arched"] == "yes" for r in rows if r["w"] == w) / sum(1 for r in rows if r["w"] == w) for w in widths]
    falls = all(a >= b for a, b in zip(fractions, fractions[1:]))
    f.write(f"\n- {'holds' if falls else 'DOES NOT HOLD'}: the share of runs that arch does not grow with the orifice "
            f"({', '.join(f'{x:.2f}' for x in fractions)})\n")
    f.write(f"- {'holds' if fractions and fractions[0] > 0 else 'DOES NOT HOLD'}: the smallest orifice arches (the thesis's Figure 2.18)\n")
print(open(md).read())
PY
gnuplot -e "dir='$dir'" plots/corn_arching.gp
echo "wrote $dir/summary.csv, studies/hopper/corn.md, plots/fig-2.17.png"
