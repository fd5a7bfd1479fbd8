# test: chung_ooi_oblique/test5_normalised_recoil_sphere_plane
# Chung & Ooi (2011) test 5 with the Hertz-Mindlin law, dt = t_c/400: a sphere strikes a rigid plane
# at v_n = 5 m/s with tangential speeds psi1 = s0/(mu v_n), mu = 0.3, e = 1; steel and
# polyethylene. (a) normalised recoil psi2 = s'/(mu v_n'), (b) normalised spin R w'/(mu v_n).
# Points: blaze; solid lines: the same model by GSL rk8pd; dashed: rigid-body impulse theory
# (sliding above psi1 = 7: psi2 = psi1 - 7, spin -5; rolling below). The dip below zero is the
# elastic sphere's negative recoil (Maw, Barber & Fawcett 1976).
set terminal pngcairo size 1200,520 font ',11'
set output 'plots/fig-chung-ooi-5.png'
set multiplot layout 1,2 title 'Chung and Ooi (2011) test 5: v_n = 5 m/s, mu = 0.3, e = 1 (points: blaze, lines: rk8pd reference, dashed: rigid-body theory)'
f = datadir.'/fig-chung-ooi-5.dat'
set xlabel 'normalised incident angle psi_1 = s_0 / (mu v_n)'
set xrange [0:16]
set grid
set key top left font ',9'
set title '(a) normalised recoil angle'
set ylabel 'psi_2 = s'' / (mu v_n'')'
set yrange [-4:9]
plot f index 1 using 1:4 with lines lw 1.5 lc 1 title 'steel, reference', \
     f index 1 using 1:6 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 0 using 1:2 with points pt 7 ps 1.0 lc 1 title 'steel, blaze', \
     f index 3 using 1:4 with lines lw 1.5 lc 2 title 'polyethylene, reference', \
     f index 2 using 1:2 with points pt 5 ps 0.9 lc 2 title 'polyethylene, blaze'
set title '(b) normalised rebound spin'
set ylabel 'R w'' / (mu v_n)'
set yrange [-6:0.5]
set key top right
plot f index 1 using 1:5 with lines lw 1.5 lc 1 title 'steel, reference', \
     f index 1 using 1:7 with lines dt 2 lc 'gray' title 'rigid body (both)', \
     f index 0 using 1:3 with points pt 7 ps 1.0 lc 1 title 'steel, blaze', \
     f index 3 using 1:5 with lines lw 1.5 lc 2 title 'polyethylene, reference', \
     f index 2 using 1:3 with points pt 5 ps 0.9 lc 2 title 'polyethylene, blaze'
unset multiplot
