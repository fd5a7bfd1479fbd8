# test: oblique_friction
# Thesis Fig 3.17: |F_t| against the slip speed at the contact point for the two scenes of Fig
# 3.16 (touching samples), coloured by the branch of F_t = min(mu F_n, K_T |v_t|): viscous (K_T
# |v_t| < mu F_n) or Coulomb. Lines: K_T |v_t| and mu m g (the sliding force). With the thesis's
# K_T = 4e3 kg/s the viscous branch lies below ~1 mm/s; with K_T = 0.5 kg/s (cube) it carries the
# impact at high slip speed.
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.17.png'
o = datadir.'/fig-3.17-octahedron.dat'
c = datadir.'/fig-3.17-cube.dat'
set multiplot layout 1,2 title 'Fig 3.17: |F_t| vs slip speed (history-free friction)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel '|v_t| at the contact point (m/s)'
set ylabel '|F_t| (N)'
set key bottom right font ',9'
viscous(ft, fn, mu) = ft < mu * fn * (1 - 1e-9)
set title 'octahedron, {/Symbol m} = 1.54, K_T = 4e3 kg/s'
set key top left
set xrange [1e-5:10]
mu = 1.54; kt = 4e3; mg = 5.2083e-5 * 9.81
plot o using 1:(viscous($2, $3, mu) ? 1/0 : $2) with points pt 7 ps 0.4 lc 1 title 'Coulomb {/Symbol m} F_n', \
     o using 1:(viscous($2, $3, mu) ? $2 : 1/0) with points pt 7 ps 0.6 lc 2 title 'viscous K_T |v_t|', \
     kt * x with lines lc 'gray' title 'K_T |v_t|', mu * mg with lines dt 2 lc 'black' title '{/Symbol m} m g'
set title 'cube, {/Symbol m} = 0.5, K_T = 0.5 kg/s'
set key bottom right
set xrange [1e-3:1]
set yrange [1e-6:10]
mu = 0.5; kt = 0.5; mg = 6.0141e-5 * 9.81
plot c using 1:(viscous($2, $3, mu) ? 1/0 : $2) with points pt 7 ps 0.4 lc 1 title 'Coulomb {/Symbol m} F_n', \
     c using 1:(viscous($2, $3, mu) ? $2 : 1/0) with points pt 7 ps 0.6 lc 2 title 'viscous K_T |v_t|', \
     kt * x with lines lc 'gray' title 'K_T |v_t|', mu * mg with lines dt 2 lc 'black' title '{/Symbol m} m g'
unset multiplot
