# make fig-3.22: thesis Fig 3.22, polyhedron-world contact against N for shapes of different face
# counts (K6000; no values in its text). Ours: the world phase (CUDA events), box of six walls.
load 'plots/perf/style.gp'
set output 'plots/perf/fig-3.22.png'
set title 'Fig 3.22: world contact vs N by shape (thesis: K6000, no values given)'
set ylabel 'ms per step (world contact)'
set label 'falling beds at 1e7: timed over 40 steps, before their first collisions' at graph 0.98, graph 0.04 right font ',8'
data = 'plots/perf/data/fig-3.22.dat'
plot for [i=0:4] data index i u 1:2 title columnheader(1)
