# make fig-3.25: thesis Fig 3.25, polyhedron-world contact against N for cubes (K6000): "0.25
# seconds for 34 million particles". Ours: the world phase of packed cubes (six walls), H200.
load 'plots/perf/style.gp'
set output 'plots/perf/fig-3.25.png'
set title 'Fig 3.25: cube-world contact vs N'
set ylabel 'ms per step (world contact)'
data = 'plots/perf/data/fig-3.25.dat'
plot data index 0 u 1:2 title columnheader(1), \
     '-' u 1:2 w p pt 7 ps 1.5 lc rgb 'red' title 'thesis, K6000, 34e6 cubes: 0.25 s'
3.4e7 250
e
