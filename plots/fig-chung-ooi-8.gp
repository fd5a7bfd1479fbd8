# test: chung_ooi_oblique/test8_spun_sphere_on_a_larger_sphere
# Chung & Ooi (2011) test 8 with the Hertz-Mindlin law, dt = t_c/400: a sphere R1 = 0.1 m spun to
# s0 = v_n tan(theta) (no tangential velocity) strikes a sphere R2 = 0.5 m at rest at v_n = 0.2 m/s,
# mu = 0.4, e = 0.5; aluminium alloy and nylon, both spin directions. (a) beta = s'/s0 against
# 3.5 mu (1+e) v_n / |s0|, (b) tangent of the recoil angle s'/v_n' against s0/v_n (top- and
# backspin mirror each other). Points: blaze; solid lines: the same model by GSL rk8pd; dashed:
# rigid-body impulse theory.
set terminal pngcairo size 1200,520 font ',11'
set output 'plots/fig-chung-ooi-8.png'
set multiplot layout 1,2 title 'Chung and Ooi (2011) test 8: spun sphere on a sphere 5x larger (points: blaze, lines: rk8pd reference, dashed: rigid-body theory)'
f = datadir.'/fig-chung-ooi-8.dat'
set grid
set key bottom right font ',9'
set title '(a) slip ratio'
set xlabel '3.5 mu (1+e) v_n / |s_0|'
set ylabel 'beta = s'' / s_0'
set xrange [0:25]
set yrange [-1:0.8]
plot f index 1 using 2:5 with lines lw 1.5 lc 1 title 'Al alloy, reference', \
     f index 1 using 2:7 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 0 using (abs($2)):3 with points pt 7 ps 1.0 lc 1 title 'Al alloy, blaze (both spins)', \
     f index 3 using 2:5 with lines lw 1.5 lc 2 title 'nylon, reference', \
     f index 2 using (abs($2)):3 with points pt 5 ps 0.9 lc 2 title 'nylon, blaze (both spins)'
set title '(b) recoil angle, both spin directions'
set xlabel 'tan(incident angle) = s_0 / v_n'
set ylabel 'tan(recoil angle) = s'' / v_n'''
set xrange [-7:7]
set yrange [-9:9]
set key top left
plot f index 1 using 1:6 with lines lw 1.5 lc 1 title 'Al alloy, reference', \
     f index 1 using (-$1):(-$6) with lines lw 1.5 lc 1 notitle, \
     f index 1 using 1:8 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 1 using (-$1):(-$8) with lines dt 2 lc 'gray' notitle, \
     f index 0 using 1:4 with points pt 7 ps 1.0 lc 1 title 'Al alloy, blaze', \
     f index 3 using 1:6 with lines lw 1.5 lc 2 title 'nylon, reference', \
     f index 3 using (-$1):(-$6) with lines lw 1.5 lc 2 notitle, \
     f index 2 using 1:4 with points pt 5 ps 0.9 lc 2 title 'nylon, blaze'
unset multiplot
