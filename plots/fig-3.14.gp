# test: cube_at_rest/cube_dropped_on_face_settles_at_static_penetration
# Thesis Fig 3.14: height of a cube (bounding radius 2.5 mm, 2500 kg/m^3 assumed) dropped flat
# from 0.2 mm onto a planar floor, Hertz K_n = 1e9 N/m^1.5 with K_D = 5e4 kg s^-1 m^-1/2
# (delta^(1/2) damping) and the no-tension clamp, dt = 2e-7 s. In SI units the thesis's K_D nearly
# stops the cube at the first impact (one small hop; the thesis shows several contacts). Right:
# the penetration settling on the static value delta_s = (m g / K_n)^(2/3).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.14.png'
f = datadir.'/fig-3.14.dat'
set multiplot layout 1,2 title 'Fig 3.14: cube dropped on its face, K_n = 1e9 N/m^{1.5}, K_D = 5e4'
set title 'centre-of-mass height'
set xlabel 't (ms)'
set ylabel 'y (mm)'
set key top right
plot f using ($1*1e3):2 with lines lw 2 title 'blaze', f using ($1*1e3):3 with lines dt 2 lc 'black' title 'h - {/Symbol d}_s'
set title 'penetration after the impact'
set xlabel 't (ms)'
set ylabel 'h - y (nm)'
set logscale y
set xrange [6.3:7.5]
set yrange [1:1000]
plot f using ($1*1e3):4 with lines lw 2 title 'blaze', f using ($1*1e3):5 with lines dt 2 lc 'black' title '{/Symbol d}_s = (m g / K_n)^{2/3} = 7.0 nm'
unset multiplot
