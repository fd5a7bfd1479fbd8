# test: chung_ooi_oblique/test4_oblique_sphere_plane
# Chung & Ooi (2011, Granular Matter 13:643) test 4 with the Hertz-Mindlin law, dt = t_c/400: a
# sphere R = 2.5 mm strikes a rigid plane at 3.9 m/s, theta from the normal, no spin, mu = 0.092,
# e = 0.98; alumina and aluminium alloy. Points: blaze; solid lines: the same model integrated by
# GSL rk8pd (reference); dashed: rigid-body impulse theory (gross sliding above 32.5 degrees,
# rolling below). (a) tangential restitution v_t'/v_t, (b) rebound spin, (c) rebound angle of the
# contact point atan(s'/v_n').
set terminal pngcairo size 1500,520 font ',11'
set output 'plots/fig-chung-ooi-4.png'
set multiplot layout 1,3 title 'Chung and Ooi (2011) test 4: oblique impact on a rigid plane, |v| = 3.9 m/s (points: blaze, lines: rk8pd reference, dashed: rigid-body theory)'
f = datadir.'/fig-chung-ooi-4.dat'
set xlabel 'incident angle theta (deg)'
set xrange [0:90]
set key bottom right font ',9'
set title '(a) tangential restitution'
set ylabel 'v_t'' / v_t'
set yrange [0.4:1.02]
plot f index 1 using 1:5 with lines lw 1.5 lc 1 title 'alumina, reference', \
     f index 1 using 1:8 with lines dt 2 lc 1 title 'alumina, rigid body', \
     f index 0 using 1:2 with points pt 7 ps 1.0 lc 1 title 'alumina, blaze', \
     f index 3 using 1:5 with lines lw 1.5 lc 2 title 'Al alloy, reference', \
     f index 3 using 1:8 with lines dt 2 lc 2 title 'Al alloy, rigid body', \
     f index 2 using 1:2 with points pt 5 ps 0.9 lc 2 title 'Al alloy, blaze'
set title '(b) rebound spin'
set ylabel 'w'' (rad/s)'
set yrange [-800:50]
set key bottom right
plot f index 1 using 1:6 with lines lw 1.5 lc 1 title 'alumina, reference', \
     f index 1 using 1:9 with lines dt 2 lc 1 title 'alumina, rigid body', \
     f index 0 using 1:3 with points pt 7 ps 1.0 lc 1 title 'alumina, blaze', \
     f index 3 using 1:6 with lines lw 1.5 lc 2 title 'Al alloy, reference', \
     f index 3 using 1:9 with lines dt 2 lc 2 title 'Al alloy, rigid body', \
     f index 2 using 1:3 with points pt 5 ps 0.9 lc 2 title 'Al alloy, blaze'
set title '(c) rebound angle of the contact point'
set ylabel 'atan(s'' / v_n'') (deg)'
set yrange [-20:90]
set key top left
plot f index 1 using 1:7 with lines lw 1.5 lc 1 title 'alumina, reference', \
     f index 1 using 1:10 with lines dt 2 lc 1 title 'alumina, rigid body', \
     f index 0 using 1:4 with points pt 7 ps 1.0 lc 1 title 'alumina, blaze', \
     f index 3 using 1:7 with lines lw 1.5 lc 2 title 'Al alloy, reference', \
     f index 3 using 1:10 with lines dt 2 lc 2 title 'Al alloy, rigid body', \
     f index 2 using 1:4 with points pt 5 ps 0.9 lc 2 title 'Al alloy, blaze'
unset multiplot
