# test: octahedron_on_cube/elastic_rebound_and_peak_penetration
# Thesis Fig 3.9: penetration vs time for the head-on elastic collision of an octahedron (vertex
# first) with a resting free cube, bounding radii 2.5 mm, 2500 kg/m^3 (assumed), Hertz K_n = 1e9
# N/m^1.5 (thesis: "N.cm^-1"), V = 0.0625 ... 4 m/s, dt = t_c/200 per speed (thesis: 1e-5 s for all,
# about one step per contact at 4 m/s). Right: peak penetration against the closed form
# (5 m_eff V^2 / 4 K_n)^(2/5).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.9.png'
f = datadir.'/fig-3.9.dat'
p = datadir.'/fig-3.9-peaks.dat'
set multiplot layout 1,2 title 'Fig 3.9: octahedron onto a free cube, elastic Hertz K_n = 1e9 N/m^{1.5}, dt = t_c/200'
set title 'penetration vs time (t = 0 at first touch)'
set xlabel 't ({/Symbol m}s)'
set ylabel 'penetration {/Symbol d} ({/Symbol m}m)'
set key top right font ',9'
set yrange [0:*]
speeds = '0.0625 0.125 0.25 0.5 1 2 4'
plot for [k = 0:6] f index k using 1:2 with lines lw 2 title 'V = '.word(speeds, k + 1).' m/s'
set title '{/Symbol d}_{max} vs V: closed form {/Symbol \265} V^{4/5}'
set logscale xy
set xlabel 'V (m/s)'
set ylabel '{/Symbol d}_{max} ({/Symbol m}m)'
set key top left
set yrange [*:*]
plot p using 1:3 with lines lw 1 lc 'gray' title '(5 m_{eff} V^2 / 4 K_n)^{2/5}', \
     p using 1:2 with points pt 7 ps 1.3 lc 1 title 'blaze'
unset multiplot
