# test: chung_ooi
# Chung & Ooi (2011, Granular Matter 13:643) benchmarks 1-3 with the Hertz law, dt = t_c/1000:
# (a) test 1 force history, two spheres R = 10 mm at 2 x 10 m/s (glass, limestone); (b) test 2, a
# sphere R = 0.1 m at 0.2 m/s onto a rigid plane (Al and Mg alloy); lines: Hertz theory F(t);
# (c) test 3, output vs input restitution, R = 2.5 mm at 3.9 m/s (alumina, cast iron), free contact
# and no-tension clamp; (d) the relative restitution error of (c) (issue bound 1%).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-chung-ooi.png'
set multiplot layout 2,2 title 'Chung and Ooi (2011) tests 1-3, Hertz law, dt = t_c/1000 (points: blaze, lines: Hertz theory)'
f1 = datadir.'/fig-chung-ooi-1.dat'
f2 = datadir.'/fig-chung-ooi-2.dat'
f3 = datadir.'/fig-chung-ooi-3.dat'
set key top right font ',9'
set xlabel 'time from first touch (us)'
set ylabel 'normal force (kN)'
set title '(a) test 1: two spheres, R = 10 mm, 2 x 10 m/s'
plot f1 index 0 every 25 using 1:2 with points pt 7 ps 0.6 lc 1 title 'glass', \
     f1 index 0 using 1:3 with lines lw 1.5 lc 1 notitle, \
     f1 index 1 every 25 using 1:2 with points pt 5 ps 0.6 lc 2 title 'limestone', \
     f1 index 1 using 1:3 with lines lw 1.5 lc 2 notitle
set title '(b) test 2: sphere on rigid plane, R = 0.1 m, 0.2 m/s'
plot f2 index 0 every 25 using 1:2 with points pt 7 ps 0.6 lc 3 title 'Al alloy', \
     f2 index 0 using 1:3 with lines lw 1.5 lc 3 notitle, \
     f2 index 1 every 25 using 1:2 with points pt 5 ps 0.6 lc 4 title 'Mg alloy', \
     f2 index 1 using 1:3 with lines lw 1.5 lc 4 notitle
set title '(c) test 3: R = 2.5 mm, 3.9 m/s (both materials alike: e is scale-free)'
set xlabel 'input restitution e_{in}'
set ylabel 'output restitution e_{out}'
set key top left
set xrange [0:1.05]
set yrange [0:1.05]
plot x with lines lc 'gray' title 'e_{out} = e_{in}', \
     f3 index 0 using 1:2 with points pt 7 ps 1.2 lc 1 title 'alumina, free', \
     f3 index 0 using 1:3 with points pt 6 ps 2.0 lc 1 title 'alumina, no tension', \
     f3 index 1 using 1:2 with points pt 5 ps 1.0 lc 2 title 'cast iron, free', \
     f3 index 1 using 1:3 with points pt 4 ps 1.6 lc 2 title 'cast iron, no tension'
set title '(d) test 3: |e_{out}/e_{in} - 1|, e_{in} < 1 (e_{in} = 1 is exact)'
set ylabel 'relative error'
set logscale y
set format y '10^{%L}'
set yrange [1e-5:1]
set xrange [0:1]
set key top right
plot 0.01 with lines dt 2 lc 'red' title '1% bound', \
     f3 index 0 using 1:($1 < 1 ? abs($2/$1 - 1) : 1/0) with linespoints pt 7 lc 1 title 'alumina, free', \
     f3 index 0 using 1:($1 < 1 ? abs($3/$1 - 1) : 1/0) with linespoints pt 6 dt 2 lc 1 title 'alumina, no tension', \
     f3 index 1 using 1:($1 < 1 ? abs($2/$1 - 1) : 1/0) with linespoints pt 5 lc 2 title 'cast iron, free', \
     f3 index 1 using 1:($1 < 1 ? abs($3/$1 - 1) : 1/0) with linespoints pt 4 dt 2 lc 2 title 'cast iron, no tension'
unset multiplot
