# test: cube_spin
# Thesis Fig 2.9 (section 2.3.2.1): a 10 mm cube spinning torque-free at w = (2 pi, 0, 0) rad/s (one
# revolution per second; the thesis's 359.944 degrees after 1 s implies it), dt = 1e-5 s, 1 s,
# velocity Verlet, float and double: (a) rotation angle vs t against |w| t, (b) the path (y, z) of
# the vertex (5, 5, 5) mm against its circle, (c) angle error, (d) the vertex's distance from its
# circle over the edge. Thesis: 359.944 deg, 0.015% error; bounds here 1e-6 (float), 1e-9 (double).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-2.9.png'
f = datadir.'/fig-2.9.dat'
r0 = sqrt(2.0) * 5.0   # mm, radius of the vertex's circle
set multiplot layout 2,2 title 'Fig 2.9: cube spinning at 2{/Symbol p} rad/s about x, dt = 1e-5 s (thesis: 359.944 deg after 1 s, 0.015%)'
set key top left font ',9'
set title '(a) rotation angle'
set xlabel 't (s)'
set ylabel '{/Symbol q} (deg)'
plot f index 1 using 1:3 with lines lw 2 lc 'gray' title '360 t (exact)', \
     f index 0 every 4 using 1:2 with points pt 6 lc 1 title 'float', \
     f index 1 every 4::2 using 1:2 with points pt 2 lc 3 title 'double'
set title '(b) vertex path: circle (gray), float (o), double (x)'
unset key
set xlabel 'y (mm)'
set ylabel 'z (mm)'
set size ratio -1
set parametric
set trange [0:2*pi]
set xrange [-8:8]
set yrange [-8:8]
plot r0 * cos(t), r0 * sin(t) with lines lw 2 lc 'gray' title 'circle', \
     f index 0 every 2 using ($4*1e3):($5*1e3) with points pt 6 ps 0.8 lc 1 title 'float', \
     f index 1 every 2::1 using ($4*1e3):($5*1e3) with points pt 2 ps 0.8 lc 3 title 'double'
unset parametric
set size noratio
set autoscale xy
set logscale y
set format y '10^{%L}'
set key bottom right font ',9'
set title '(c) |{/Symbol q} - 2{/Symbol p} t| (rad)'
set xlabel 't (s)'
set ylabel 'angle error (rad)'
set yrange [1e-18:1e-4]
plot f index 0 using 1:(abs($6) > 0 ? abs($6) : 1e-18) with lines lw 2 lc 1 title 'float', \
     f index 1 using 1:(abs($6) > 0 ? abs($6) : 1e-18) with lines lw 2 lc 3 title 'double', \
     2*pi*1e-6 with lines dt 2 lc 1 title 'float bound (1e-6 of a turn)'
set title '(d) vertex distance from its circle / edge'
set yrange [1e-18:1e-2]
set key top right font ',9'
set ylabel 'distance / edge'
plot f index 0 using 1:($7 + 1e-18) with lines lw 2 lc 1 title 'float', \
     f index 1 using 1:($7 + 1e-18) with lines lw 2 lc 3 title 'double', \
     1e-6 with lines dt 2 lc 1 title 'bound 1e-6'
unset multiplot
