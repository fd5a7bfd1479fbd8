# test: oblique_friction
# Thesis Fig 3.16: position and tangential velocity after an oblique impact with history-free
# friction. Top: the thesis's scene, an octahedron (bounding radius 2.5 mm, vertex down) thrown
# with v_t = 2 m/s, v_n = -0.5 m/s from 0.75 cm, K_n = 1e9 N/m^1.5, K_D = 2e5, mu = 1.54,
# K_T = 4e3 kg/s, dt = 1e-7 s: mu is beyond its tipping limits, so it tumbles. Bottom: the
# asserted scene, a cube landing flat (v_t = 0.5 m/s, v_n = -0.5 m/s, K_D = 5e4 with the
# no-tension clamp, mu = 0.5, K_T = 0.5 kg/s, dt = 2e-7 s for the impact, then 1e-6 s), sliding
# with slope mu g (dashed: the Coulomb line over the fitted window).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.16.png'
o = datadir.'/fig-3.16-octahedron.dat'
c = datadir.'/fig-3.16-cube.dat'
cf = datadir.'/fig-3.16-cube-fit.dat'
set multiplot layout 2,2 title 'Fig 3.16: oblique impact with friction'
set xlabel 't (s)'
set title 'octahedron (thesis scene, {/Symbol m} = 1.54): height of the centre'
set ylabel 'y (mm)'
plot o using 1:3 with lines lw 2 notitle
set title 'octahedron: tangential velocity of the centre'
set ylabel 'v_x (m/s)'
plot o using 1:4 with lines lw 2 notitle
set title 'cube (mu = 0.5): height of the centre'
set ylabel 'y (mm)'
plot c using 1:3 with lines lw 2 notitle
set title 'cube: v_x, and v(t_a) - {/Symbol m} g (t - t_a)'
set ylabel 'v_x (m/s)'
plot c using 1:4 with lines lw 2 title 'blaze', cf using 1:2 with lines dt 2 lw 2 lc 'black' title 'slope -{/Symbol m} g'
unset multiplot
