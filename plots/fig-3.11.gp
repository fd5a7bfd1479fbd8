# test: octahedron_on_cube/elastic_rebound_and_peak_penetration
# Thesis Fig 3.11: velocities through the head-on elastic collision (octahedron onto a resting
# free cube, K_n = 1e9 N/m^1.5, V = 0.0625 ... 4 m/s, dt = t_c/200), scaled by V against time in
# units of each speed's contact time t_c = 2.9432 delta_max / V: all speeds collapse onto one curve
# and end on the 1-D elastic collision values (dashed).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.11.png'
f = datadir.'/fig-3.11.dat'
set title 'Fig 3.11: velocities / V through the contact, 7 speeds (thesis Table 3.1: errors up to 0.36%)'
set xlabel 't / t_c (t = 0 at first touch)'
set ylabel 'v_y / V'
set key center right font ',9'
set xrange [-0.1:1.3]
speeds = '0.0625 0.125 0.25 0.5 1 2 4'
plot for [k = 0:6] f index k using 1:2 with lines lw 2 lc k + 1 title 'octahedron, V = '.word(speeds, k + 1), \
     for [k = 0:6] f index k using 1:3 with lines lw 2 dt 3 lc k + 1 notitle, \
     f index 0 using 1:4 with lines lw 1 dt 2 lc 'black' title "-(m_o - m_c)/(m_o + m_c)", \
     f index 0 using 1:5 with lines lw 1 dt 2 lc 'gray40' title '-2 m_o/(m_o + m_c) (cube, dotted)'
