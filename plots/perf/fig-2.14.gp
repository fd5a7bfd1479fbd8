# make fig-2.14: thesis Fig 2.14, time per step against N for octahedra (Tesla K20, gravity packing
# up to 1e6). The thesis gives no values (its text says "scales linearly up to a million"). Ours:
# the whole step (particle-steps/s from the unfenced timed stretch), H200, falling from a loose
# lattice (at 1e7 the timed steps end before the first collisions).
load 'plots/perf/style.gp'
set output 'plots/perf/fig-2.14.png'
set title 'Fig 2.14: time per step vs N (thesis: octahedra on a K20, no values given, "linear")'
set ylabel 'ms per step'
set label 'falling beds at 1e7: timed over 40 steps, before their first collisions' at graph 0.98, graph 0.04 right font ',8'
data = 'plots/perf/data/fig-2.14.dat'
plot for [i=0:2] data index i u 1:2 title columnheader(1), \
     [1e4:1e7] 1.4 * x / 1e6 dt 2 lc rgb 'gray' title 'linear in N (through octahedra at 1e6)'
