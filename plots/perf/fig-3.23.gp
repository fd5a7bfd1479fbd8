# make fig-3.23: thesis Fig 3.23, polyhedron-polyhedron contact against N for different polyhedra
# (K6000; no values in its text, "linear"). Ours: the contact phase (CUDA events), falling beds
# (few contacts) and packed beds (every body pressed on its neighbours).
load 'plots/perf/style.gp'
set output 'plots/perf/fig-3.23.png'
set title 'Fig 3.23: polyhedron-polyhedron contact vs N by shape (thesis: K6000, no values given)'
set ylabel 'ms per step (particle contact)'
set label 'falling beds at 1e7: timed over 40 steps, before their first collisions' at graph 0.98, graph 0.04 right font ',8'
data = 'plots/perf/data/fig-3.23.dat'
plot for [i=0:4] data index i u 1:2 title columnheader(1)
