# make fig-3.24: thesis Fig 3.24, polyhedron-polyhedron contact against N for cubes up to 34e6
# (K6000). Its text gives no time for this phase; its whole step at 34e6 took 13 s (Table 3.3),
# an upper bound, drawn as one. Ours: the contact phase of packed cubes up to 1e8 (H200).
load 'plots/perf/style.gp'
set output 'plots/perf/fig-3.24.png'
set title 'Fig 3.24: cube-cube contact vs N'
set ylabel 'ms per step (particle contact)'
set arrow from 3.4e7,13000 to 3.4e7,3250 lw 2 lc rgb 'red'
data = 'plots/perf/data/fig-3.24.dat'
plot data index 0 u 1:2 title columnheader(1), \
     '-' u 1:2 w p pt 7 ps 1.5 lc rgb 'red' title 'thesis, K6000, 34e6 cubes: below its whole step (13 s) (arrow: an upper bound)'
3.4e7 13000
e
