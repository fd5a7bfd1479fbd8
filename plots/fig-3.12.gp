# test: force_hysteresis/damping_work_equals_kinetic_energy_loss
# Thesis Fig 3.12: normal force vs penetration for an octahedron (bound_R 2.5 mm, 2500 kg/m^3)
# falling vertex-first at V = 2 m/s onto a planar wall, Hertz K_n = 1e9 N/m^1.5 with delta^(1/2)
# damping: (a) the thesis's K_D = 5e4 kg s^-1 m^-1/2 (overdamped in SI units: the body stops and
# creeps out), (b) K_D = 5e2 (the bouncing loop of the thesis's figure); free contact (attractive
# near separation) and the no-tension clamp. dt = t_c/1000 (thesis: 1e-5 s).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.12.png'
f = datadir.'/fig-3.12.dat'
set multiplot layout 1,2 title 'Fig 3.12: normal force vs penetration, octahedron vertex-first, V = 2 m/s, K_n = 1e9 N/m^{1.5} (thesis: qualitative loop)'
set xlabel 'penetration {/Symbol d} ({/Symbol m}m)'
set ylabel 'normal force on the body (N)'
set key top right font ',9'
set xzeroaxis lt 0
set title '(a) K_D = 5e4 (thesis value)'
plot f index 0 using 1:2 with lines lw 2 lc 1 title 'F_N, free contact', \
     f index 1 using 1:2 with lines lw 2 dt 2 lc 2 title 'F_N, no-tension clamp', \
     f index 0 using 1:3 with lines lw 1 lc 'gray' title 'elastic K_n {/Symbol d}^{1.5}'
set title '(b) K_D = 5e2'
plot f index 2 using 1:2 with lines lw 2 lc 1 title 'F_N, free contact', \
     f index 3 using 1:2 with lines lw 2 dt 2 lc 2 title 'F_N, no-tension clamp', \
     f index 2 using 1:3 with lines lw 1 lc 'gray' title 'elastic K_n {/Symbol d}^{1.5}'
unset multiplot
