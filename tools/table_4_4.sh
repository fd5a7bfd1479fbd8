#!/usr/bin/env bash
# make table-4.4: the 3D laboratory mill of thesis section 4.2.1 (Table 4.4) with two contact laws,
# each case a run of study_mill (studies/mill/main.cpp):
#   history_free   the scene files as they are: linear spring-dashpot, K_n = 4e5 N/m, e = 0.825,
#                  mu = 0.15 through the thesis's eq. 4.3 friction (its GPU law)
#   hertz_mindlin  the same charge with Hertz (steel, E = 2 GPa, nu = 0.3: a hundredth of steel's
#                  modulus, so that the CPU runs the table in minutes; the charge's motion is set by
#                  e and mu, not by the stiffness: K_n from 4e5 to 4e6 N/m moved the 20% / 32 rpm
#                  power by 1%) and the Mindlin tangential spring, e = 0.825, mu = 0.15
# for 20% filling (168 balls) at 14, 22, 32 rpm and 30% (243 balls) at 14 and 22 rpm, five
# revolutions at full speed (the first skipped). Writes DIR/<law>/<fill>_<rpm>rpm/{power.csv,
# manifest.txt}, with the thesis's own estimate sum |F_diss| |V| dt beside the exact methods,
# DIR/<law>/scene_*.toml (the scenes run), DIR/power.csv (one row per case, with
# the experiment's and the thesis's power), studies/mill/table-4.4.md, plots/fig-mill-power.png and
# plots/fig-mill-profile.png (the time-averaged charges of the thesis's Figures 4.9-4.12).
# Usage: tools/table_4_4.sh STUDY_BINARY [DIR]        (DIR defaults to data/mill/table-4.4)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$1 dir=${2:-data/mill/table-4.4}
mkdir -p "$dir"
# fill rpm experiment_W thesis_W (thesis Table 4.4)
cases="20 14 301 336
20 22 459 437
20 32 532 520
30 14 393 409
30 22 617 636"
out="$dir/power.csv"
echo "law,filling_pc,rpm,experiment_W,thesis_W,torque_method_W,energy_method_W,error_pc,share_pair_pc,share_shell_pc,share_lifter_pc,share_end_plate_pc,wall_time_s,thesis_estimate_W" > "$out"
for law in history_free hertz_mindlin; do
  mkdir -p "$dir/$law"
  for fill in 20 30; do
    src=studies/mill/lab_mill.toml
    [ "$fill" = 30 ] && src=studies/mill/lab_mill_30pc.toml
    scene="$dir/$law/scene_${fill}pc.toml"
    if [ "$law" = history_free ]; then
      cp "$src" "$scene"
    else
      sed -e 's/^law = "linear"/law = "hertz"\ntangential = "mindlin"/' -e '/^stiffness = /d' \
          -e 's/^density = 7800/density = 7800\nyoungs_modulus = 2.0e9\npoisson_ratio = 0.3/' "$src" > "$scene"
    fi
  done
  while read -r fill rpm experiment thesis; do
    case_dir="$dir/$law/${fill}pc_${rpm}rpm"
    period=$(python3 -c "print(60 / $rpm)")
    end=$(python3 -c "print(0.5 + 5 * 60 / $rpm + 0.01)")
    "$bin" "$dir/$law/scene_${fill}pc.toml" --set "mill.rpm=$rpm" --set "simulation.end_time=$end" \
      --set "output.directory=$case_dir" > "$case_dir.log" 2>&1 || { echo "table-4.4: $law ${fill}% ${rpm} rpm failed (see $case_dir.log)"; exit 1; }
    python3 - "$case_dir/manifest.txt" "$law" "$fill" "$rpm" "$experiment" "$thesis" >> "$out" <<'PY'
import sys
m = dict(l.rstrip("\n").split(" = ", 1) if " = " in l else l.rstrip("\n").split("=", 1) for l in open(sys.argv[1]) if "=" in l)
m = {k.strip(): v.strip() for k, v in m.items()}
law, fill, rpm, exp, thesis = sys.argv[2:7]
p = float(m["power_W"])
print(f"{law},{fill},{rpm},{exp},{thesis},{p:.1f},{float(m['energy_method_W']):.1f},{100 * (p - float(exp)) / float(exp):.1f},"
      f"{float(m['share_pair']):.1f},{float(m['share_shell']):.1f},{float(m['share_lifter']):.1f},{float(m['share_end_plate']):.1f},"
      f"{float(m['wall_time_s']):.1f},{float(m['thesis_estimate_W']):.1f}")
PY
    echo "table-4.4: $law, ${fill}% at $rpm rpm: $(tail -1 "$out")"
  done <<< "$cases"
done
python3 tools/table_4_4.py "$out" > studies/mill/table-4.4.md
gnuplot -e "csv='$out'" plots/mill_power.gp
# the time-averaged charges of the thesis's Figures 4.9-4.12 (history-free), toe and shoulder marked
args="n=4; cols=2; out='plots/fig-mill-profile.png'; R=0.45; h=0.025; vs=0.04; every=2"
k=0
for c in 20:14 20:22 30:14 30:22; do
  k=$((k + 1)) fill=${c%%:*} rpm=${c##*:} m="$dir/history_free/${fill}pc_${rpm}rpm/manifest.txt"
  toe=$(sed -n 's/^toe_deg = //p' "$m") shoulder=$(sed -n 's/^shoulder_deg = //p' "$m")
  args="$args; file$k='$dir/history_free/${fill}pc_${rpm}rpm/charge_field.csv'; sign$k=1; toe$k=$toe; shoulder$k=$shoulder"
  args="$args; title$k='${fill}% filling, $rpm rpm (history-free): toe $toe, shoulder $shoulder deg'"
done
gnuplot -e "$args" plots/mill_profile.gp
echo "wrote $out, studies/mill/table-4.4.md, plots/fig-mill-power.png, plots/fig-mill-profile.png"
