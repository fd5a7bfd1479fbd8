# test: chung_ooi_oblique/test7_two_identical_spheres_with_spin
# Chung & Ooi (2011) test 7 with the Hertz-Mindlin law, dt = t_c/400: two identical spheres
# R = 0.1 m, each at 0.2 m/s, mu = 0.4, e = 0.5, aluminium alloy and copper, both spun w0 the same
# way (s0 = 2 w0 R; spun +w0 and -w0 their surfaces move together and nothing changes, asserted
# by the test). (a) sphere 1's tangential velocity after the impact, (b) its spin. Points: blaze;
# solid lines: the same model by GSL rk8pd; dashed: rigid-body impulse theory (sliding above
# w0 = 4.2 rad/s).
set terminal pngcairo size 1200,520 font ',11'
set output 'plots/fig-chung-ooi-7.png'
set multiplot layout 1,2 title 'Chung and Ooi (2011) test 7: two identical spheres spun the same way (points: blaze, lines: rk8pd reference, dashed: rigid-body theory)'
f = datadir.'/fig-chung-ooi-7.dat'
set grid
set xlabel 'initial spin w_0 (rad/s)'
set xrange [0:26]
set key top right font ',9'
set title '(a) tangential velocity of sphere 1'
set ylabel 'v_{1t}'' (m/s)'
set yrange [-0.15:0.02]
plot f index 1 using 1:4 with lines lw 1.5 lc 1 title 'Al alloy, reference', \
     f index 1 using 1:6 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 0 using 1:2 with points pt 7 ps 1.0 lc 1 title 'Al alloy, blaze', \
     f index 3 using 1:4 with lines lw 1.5 lc 2 title 'copper, reference', \
     f index 2 using 1:2 with points pt 5 ps 0.9 lc 2 title 'copper, blaze'
set title '(b) spin of sphere 1'
set ylabel 'w_1'' (rad/s)'
set yrange [-2:25]
set key top left
plot x with lines lc 'black' dt 3 title 'w'' = w_0', \
     f index 1 using 1:5 with lines lw 1.5 lc 1 title 'Al alloy, reference', \
     f index 1 using 1:7 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 0 using 1:3 with points pt 7 ps 1.0 lc 1 title 'Al alloy, blaze', \
     f index 3 using 1:5 with lines lw 1.5 lc 2 title 'copper, reference', \
     f index 2 using 1:3 with points pt 5 ps 0.9 lc 2 title 'copper, blaze'
unset multiplot
