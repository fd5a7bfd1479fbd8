# test: chung_ooi_oblique/test6_spin_sphere_plane
# Chung & Ooi (2011) test 6 with the Hertz-Mindlin law, dt = t_c/400: a sphere R = 0.1 m strikes a
# rigid plane at v_n = 0.2 m/s, mu = 0.4, e = 0.5; aluminium alloy and nylon. (a), (b): spun only,
# s0 = v_n tan(theta); beta = s'/s0 against 3.5 mu (1+e) v_n / s0 and the tangent of the recoil
# angle s'/v_n' against s0/v_n. (c) moving at v_t = 0.2 m/s with top- and backspin (added here).
# Points: blaze; solid lines: the same model by GSL rk8pd; dashed: rigid-body impulse theory.
set terminal pngcairo size 1500,520 font ',11'
set output 'plots/fig-chung-ooi-6.png'
set multiplot layout 1,3 title 'Chung and Ooi (2011) test 6: spinning sphere on a plane, v_n = 0.2 m/s (points: blaze, lines: rk8pd reference, dashed: rigid-body theory)'
f = datadir.'/fig-chung-ooi-6.dat'
set grid
set key bottom right font ',9'
set title '(a) spin only: slip ratio'
set xlabel '3.5 mu (1+e) v_n / s_0'
set ylabel 'beta = s'' / s_0'
set xrange [0:25]
set yrange [-1:0.8]
plot f index 1 using 2:5 with lines lw 1.5 lc 1 title 'Al alloy, reference', \
     f index 1 using 2:7 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 0 using 2:3 with points pt 7 ps 1.0 lc 1 title 'Al alloy, blaze', \
     f index 5 using 2:5 with lines lw 1.5 lc 2 title 'nylon, reference', \
     f index 4 using 2:3 with points pt 5 ps 0.9 lc 2 title 'nylon, blaze'
set title '(b) spin only: recoil angle'
set xlabel 'tan(incident angle) = s_0 / v_n'
set ylabel 'tan(recoil angle) = s'' / v_n'''
set xrange [0:7]
set yrange [-2:8]
set key top left
plot f index 1 using 1:6 with lines lw 1.5 lc 1 title 'Al alloy, reference', \
     f index 1 using 1:8 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 0 using 1:4 with points pt 7 ps 1.0 lc 1 title 'Al alloy, blaze', \
     f index 5 using 1:6 with lines lw 1.5 lc 2 title 'nylon, reference', \
     f index 4 using 1:4 with points pt 5 ps 0.9 lc 2 title 'nylon, blaze'
set title '(c) v_t = 0.2 m/s with topspin (s_0 < v_t) and backspin'
set xlabel 's_0 / v_n = (v_t + R w_0) / v_n'
set xrange [-5.5:6.5]
set yrange [-8:8]
plot f index 3 using 1:6 with lines lw 1.5 lc 1 title 'Al alloy, reference', \
     f index 3 using 1:8 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 2 using 1:4 with points pt 7 ps 1.0 lc 1 title 'Al alloy, blaze', \
     f index 7 using 1:6 with lines lw 1.5 lc 2 title 'nylon, reference', \
     f index 6 using 1:4 with points pt 5 ps 0.9 lc 2 title 'nylon, blaze'
unset multiplot
