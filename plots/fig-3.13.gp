# test: force_hysteresis/restitution_depends_on_kd_times_speed_to_one_fifth
# Thesis Fig 3.13: |F_el| - |F_diss| through the contact for impact speeds 0.25-4 m/s, octahedron
# (bound_R 2.5 mm) vertex-first on a planar wall, Hertz K_n = 1e9 N/m^1.5, delta^(1/2) damping
# K_D = 5e2 (top) and the thesis's 5e4 kg s^-1 m^-1/2 (bottom, overdamped in SI units); against
# time from first touch (left) and against the approach velocity (right, as the thesis plots it).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.13.png'
f = datadir.'/fig-3.13.dat'
set multiplot layout 2,2 title 'Fig 3.13: |F_{el}| - |F_{diss}| during contact, K_n = 1e9 N/m^{1.5} (negative: damping dominates)'
set key top right font ',8'
set xzeroaxis lt 0
speeds = '0.25 0.5 1 2 4'
set ylabel '|F_{el}| - |F_{diss}| (N)'
set xlabel 'time from first touch ({/Symbol m}s)'
set title 'K_D = 5e2'
plot for [k = 0:4] f index k using 1:5 with lines lw 1.5 lc (k+1) title 'V = '.word(speeds, k+1).' m/s'
set xlabel 'approach velocity v_n (m/s)'
set title 'K_D = 5e2, vs velocity'
plot for [k = 0:4] f index k using 2:5 with lines lw 1.5 lc (k+1) title 'V = '.word(speeds, k+1).' m/s'
set xlabel 'time from first touch ({/Symbol m}s)'
set title 'K_D = 5e4 (thesis value)'
set logscale x
set xrange [1e-3:1e3]
set format x '10^{%L}'
set key bottom right
plot for [k = 5:9] f index k using 1:5 with lines lw 1.5 lc (k-4) title 'V = '.word(speeds, k-4).' m/s'
unset logscale x
set xrange [*:*]
set format x '%g'
set xlabel 'approach velocity v_n (m/s)'
set title 'K_D = 5e4, vs velocity'
plot for [k = 5:9] f index k using 2:5 with lines lw 1.5 lc (k-4) title 'V = '.word(speeds, k-4).' m/s'
unset multiplot
