# test: incline/rolls_iff_tan_theta_below_three_and_a_half_mu
# Ball on an incline (standard check): sphere r = 5 mm released at rest, history-free friction
# (K_T = 1 kg/s), 8 (theta, mu) cases on both sides of tan(theta) = 3.5 mu, dt = 2e-5 s. Left: speed
# along the slope. Right: fitted acceleration / (g sin theta) against tan(theta)/mu with the rigid-body
# law: 5/7 (rolling) up to 3.5, then 1 - mu/tan(theta) (sliding).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-incline.png'
f = datadir.'/fig-incline.dat'
s = datadir.'/fig-incline-summary.dat'
set multiplot layout 1,2 title 'Ball on an incline: rolls iff tan {/Symbol q} <= 3.5 {/Symbol m}'
set title 'speed along the slope'
set xlabel 't (s)'
set ylabel 'v (m/s)'
set key top left font ',8' title '{/Symbol q} (deg) / {/Symbol m}'
names = '10/0.3 30/0.2 33/0.2 55/0.5 37/0.2 45/0.2 20/0.05 70/0.5'
plot for [k = 0:7] f index k using 1:2 with lines lw 2 title word(names, k + 1).(k < 4 ? ' rolls' : ' slides')
set title 'a / (g sin {/Symbol q}) vs tan {/Symbol q} / {/Symbol m}'
set xlabel 'tan {/Symbol q} / {/Symbol m}'
set ylabel 'a / (g sin {/Symbol q})'
set xrange [0:8]
set yrange [0.6:1]
set key bottom right
set samples 500
law(x) = x <= 3.5 ? 5.0/7 : 1 - 1/x
plot law(x) with lines lw 2 lc 'gray' title 'rigid body: 5/7, then 1 - {/Symbol m}/tan {/Symbol q}', \
     s using 1:2 with points pt 7 ps 1.5 lc 1 title 'blaze'
unset multiplot
