# test: energy_conservation
# Thesis Fig 2.8 (section 2.3.2): total energy error (E - E0)/E0 of 48 elastic frictionless spheres
# (r = 5 cm) falling into a box for 1 s, velocity Verlet in double, dt = 1e-4, 5e-5, 2.5e-5 and
# 1.25e-5 s; contact time 5 ms (50 steps at the thesis's 1e-4 s). (a) Hertz, (b) linear spring;
# (c, d) the same errors times (1e-4 s / dt)^2: second order makes the curves coincide. The linear
# spring's force kink at touch leaves an erratic O(dt^2) residual after each contact (random walk).
# Thesis: ~1% at dt = 1e-4 s; bound here 0.1%.
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-2.8.png'
hz = datadir.'/fig-2.8-hertz.dat'
ln = datadir.'/fig-2.8-linear.dat'
dts = '1e-4 5e-5 2.5e-5 1.25e-5'
set multiplot layout 2,2 title 'Fig 2.8: energy error, 48 spheres falling onto a plane, velocity Verlet (thesis: about 1% at dt = 1e-4 s; bound here 0.1%)'
set xlabel 't (s)'
set key bottom left font ',8' maxrows 2
set format y '%.0e'
set ylabel '(E - E_0) / E_0'
set yrange [-2.5e-4:2.5e-4]
set title '(a) Hertz'
plot for [i = 0:3] hz index i using 1:2 with lines lw 1 lc (i+1) title 'dt = '.word(dts, i+1).' s'
set title '(b) linear spring'
plot for [i = 0:3] ln index i using 1:2 with lines lw 1 lc (i+1) title 'dt = '.word(dts, i+1).' s'
set ylabel '(E - E_0) / E_0 x (10^{-4} s / dt)^2'
set title '(c) Hertz, scaled by dt^{-2}'
plot for [i = 0:3] hz index i using 1:($2 * 4**i) with lines lw 1 lc (i+1) title 'dt = '.word(dts, i+1).' s'
set title '(d) linear spring, scaled by dt^{-2}'
plot for [i = 0:3] ln index i using 1:($2 * 4**i) with lines lw 1 lc (i+1) title 'dt = '.word(dts, i+1).' s'
unset multiplot
