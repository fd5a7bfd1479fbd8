# test: drag_fall/figure_2_11_and_error_at_1e_4
# Thesis Fig 2.11 (section 2.5.1): a 1 kg sphere falling from rest under gravity and quadratic drag
# F = m g - alpha v^2, alpha = 0.5 kg/m, velocity Verlet in double at dt = 1e-3 and 1e-4 s, against
# x = (m/alpha) ln cosh(t/tau), v = V tanh(t/tau), V = sqrt(m g/alpha), tau = sqrt(m/(g alpha)):
# (a) x and v vs t, (b) pointwise relative errors (thesis: 0.10% at 1e-3 s, 0.010% at 1e-4 s).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-2.11.png'
f = datadir.'/fig-2.11.dat'
m = 1.0; alpha = 0.5; g = 9.81
tau = sqrt(m / (g * alpha)); V = sqrt(m * g / alpha)
x_exact(t) = m / alpha * log(cosh(t / tau))
v_exact(t) = V * tanh(t / tau)
set multiplot layout 2,1 title 'Fig 2.11: drag fall, m = 1 kg, {/Symbol a} = 0.5 kg/m, velocity Verlet (double)'
set xrange [0:3]
set xlabel 't (s)'
set ylabel 'fall distance x (m)'
set y2label 'speed v (m/s)'
set ytics nomirror
set y2tics
set key bottom right font ',9'
set samples 400
set title '(a) position and velocity against the closed forms'
plot x_exact(x) with lines lw 2 lc 'gray' title 'x exact', \
     f index 0 every 10 using 1:2 with points pt 6 ps 1.2 lc 1 title 'x, dt = 1e-3 s', \
     f index 1 every 10::5 using 1:2 with points pt 2 ps 0.9 lc 3 title 'x, dt = 1e-4 s', \
     v_exact(x) axes x1y2 with lines lw 2 dt 2 lc 'black' title 'v exact', \
     f index 0 every 10 using 1:3 axes x1y2 with points pt 4 ps 1.2 lc 2 title 'v, dt = 1e-3 s', \
     f index 1 every 10::5 using 1:3 axes x1y2 with points pt 1 ps 0.9 lc 4 title 'v, dt = 1e-4 s'
unset y2label
unset y2tics
set ytics mirror
set logscale y
set format y '10^{%L}'
set yrange [1e-11:10]
set ylabel 'relative error'
set key top right font ',9' maxrows 3
set title '(b) |x/x_{exact} - 1| and |v/v_{exact} - 1|; thesis bounds dashed'
plot f index 0 using 1:6 with lines lw 2 lc 1 title 'x, dt = 1e-3 s', \
     f index 0 using 1:7 with lines lw 2 lc 2 title 'v, dt = 1e-3 s', \
     f index 1 using 1:6 with lines lw 2 lc 3 title 'x, dt = 1e-4 s', \
     f index 1 using 1:7 with lines lw 2 lc 4 title 'v, dt = 1e-4 s', \
     1e-3 with lines dt 2 lc 1 title 'thesis 0.10% (dt = 1e-3 s)', \
     1e-4 with lines dt 2 lc 3 title 'thesis 0.010% (dt = 1e-4 s)'
unset multiplot
