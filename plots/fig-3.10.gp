# test: octahedron_on_cube/loading_and_unloading_coincide
# Thesis Fig 3.10: normal force on the cube vs penetration (from the body positions) for the
# head-on elastic octahedron-cube collision at V = 2 m/s, K_n = 1e9 N/m^1.5, dt = t_c/200: loading
# and unloading lie on K_n delta^{3/2} (thesis: "symmetric", qualitative).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.10.png'
f = datadir.'/fig-3.10.dat'
set title 'Fig 3.10: F_N vs penetration, octahedron onto a free cube, V = 2 m/s, K_n = 1e9 N/m^{1.5}'
set xlabel 'penetration {/Symbol d} ({/Symbol m}m)'
set ylabel 'normal force (N)'
set key top left
plot f index 0 using 1:3 with lines lw 6 lc rgb '#cccccc' title 'K_n {/Symbol d}^{3/2}', \
     f index 0 using 1:2 with points pt 7 ps 0.6 lc 1 title 'loading', \
     f index 1 using 1:2 with points pt 6 ps 1.0 lc 2 title 'unloading'
