#!/usr/bin/env bash
# make fig-beverloo: glass beads poured into a flat-bottomed cylindrical silo (an STL file per
# orifice, studies/silo/make_silo_stl.py) and discharged through orifices of D/d in BEVERLOO_RATIOS
# (default "5 8 11 13 15"), each run by the hopper study on studies/silo/beverloo.toml with Hertz-Mindlin.
# Then W = C rho_b sqrt(g) (D - k d)^(5/2) is fitted as the straight line W^(2/5) = s (D - k d):
# C = s^(5/2) / (rho_b sqrt(g)), k = -intercept / (s d). Writes DIR/D<mm>/ (each run's output),
# DIR/summary.csv, studies/silo/beverloo.md (the table, the fit against the literature's ranges and
# the checks) and plots/fig-beverloo.png. A GPU target: 70 000 beads per run.
# Usage: tools/beverloo.sh STUDY_BINARY [DIR]                (DIR defaults to data/silo/beverloo)
#   BEVERLOO_SET="feed[0].count=4000 ..." adds --set overrides to every run (small trial runs);
#   BEVERLOO_RUN=0 only summarises the runs already in DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$1 dir=${2:-data/silo/beverloo}
ratios=${BEVERLOO_RATIOS:-5 8 11 13 15}
d=0.004                  # m, the beads' diameter (studies/silo/beverloo.toml)
mkdir -p "$dir"
sets=()
for s in ${BEVERLOO_SET:-}; do sets+=(--set "$s"); done
cases=""
# the gate (a 70 mm square, studies/silo/beverloo.toml) must cover the orifice: D <= 17 d
for r in $ratios; do
  python3 -c "import sys; r = float('$r'); sys.exit(0 if 2 <= r <= 17 else 1)" 2>/dev/null \
    || { echo "beverloo: BEVERLOO_RATIOS: '$r' is not a D/d from 2 to 17 (the gate covers up to 68 mm)"; exit 1; }
done
for r in $ratios; do
  read -r D mm t_end < <(python3 -c "
from math import pi, sqrt
r = float('$r'); d = $d; D = r * d
w = 0.58 * 1510 * sqrt(9.81) * max(D - 1.5 * d, 0.5 * d) ** 2.5   # kg/s, Beverloo's estimate (C 0.58, k 1.5)
beads = 2000 * 2500 * pi / 6 * d ** 3 / w                          # s for 2000 beads
print(D, round(D * 1000, 3), 1.0 + min(3.0, max(beads, min(1.5, max(0.5, 7.5 / r)))))")
  case_dir="$dir/D$mm"
  cases="$cases $case_dir"
  [ "${BEVERLOO_RUN:-1}" = 1 ] || continue
  mkdir -p "$case_dir"
  python3 studies/silo/make_silo_stl.py --radius 0.075 --height 0.35 --orifice-radius "$(python3 -c "print($D/2)")" \
    --segments 96 --out "$case_dir/silo.stl" > /dev/null
  # the discharge lasts 7.5 / (D/d) s, 0.5 to 1.5 s (short enough that the bed stays above 2 D through
  # the largest orifice), or longer where Beverloo's rate needs it for ~2000 beads, up to 3 s: a small
  # orifice's flow comes in bursts (D/d = 5 at 1.5 s: 1068 beads, early and late rates 15% apart)
  "$bin" studies/silo/beverloo.toml --set "mesh[0].file=\"$case_dir/silo.stl\"" --set "study.orifice_half_width=$(python3 -c "print($D/2)")" \
    --set "simulation.end_time=$t_end" --set "output.directory=$case_dir" "${sets[@]}" > "$case_dir.log" 2>&1 \
    || { echo "beverloo: D = $mm mm failed (see $case_dir.log)"; tail -5 "$case_dir.log"; exit 1; }
  echo "beverloo: D = $mm mm (D/d = $r) done: $(grep -a "flow rate\|discharged" "$case_dir.log" | tail -1)"
done
python3 studies/silo/beverloo_fit.py --d "$d" --silo-radius 0.075 --summary "$dir/summary.csv" --md studies/silo/beverloo.md $cases
gnuplot -e "summary='$dir/summary.csv'" plots/beverloo.gp
echo "wrote $dir/summary.csv, studies/silo/beverloo.md, plots/fig-beverloo.png"
