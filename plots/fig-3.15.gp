# test: cube_at_rest/cube_dropped_on_face_settles_at_static_penetration
# Thesis Fig 3.15: vertical velocity of the cube of Fig 3.14 (dropped flat from 0.2 mm, K_n = 1e9
# N/m^1.5, K_D = 5e4 with the no-tension clamp, dt = 2e-7 s); right: |v_y| on a log scale falling
# below the 1e-6 m/s of the verification issue.
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.15.png'
f = datadir.'/fig-3.14.dat'
set multiplot layout 1,2 title 'Fig 3.15: cube dropped on its face, velocity'
set title 'v_y'
set xlabel 't (ms)'
set ylabel 'v_y (m/s)'
plot f using ($1*1e3):6 with lines lw 2 notitle
set title '|v_y| after the impact'
set logscale y
set format y '10^{%L}'
set xrange [6:12]
set yrange [1e-16:1]
plot f using ($1*1e3):(abs($6)) with lines lw 1 title '|v_y|', 1e-6 with lines dt 2 lc 'black' title '10^{-6} m/s'
unset multiplot
