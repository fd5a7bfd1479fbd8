# make fig-3.26: thesis Fig 3.26, the broad phase against N (K6000): "under one second a step for
# 34 million particles" (it rebuilt every step). Ours: one rebuild (hash, sort, reorder, cells and
# neighbour list; CUDA events), H200, which the neighbour-list skin needs only every ~10-30 steps.
load 'plots/perf/style.gp'
set output 'plots/perf/fig-3.26.png'
set title 'Fig 3.26: broad phase vs N'
set ylabel 'ms per rebuild (broad phase)'
set arrow from 3.4e7,1000 to 3.4e7,250 lw 2 lc rgb 'red'
data = 'plots/perf/data/fig-3.26.dat'
plot for [i=0:1] data index i u 1:2 title columnheader(1), \
     '-' u 1:2 w p pt 7 ps 1.5 lc rgb 'red' title 'thesis, K6000, 34e6 cubes: under 1 s (arrow: an upper bound)'
3.4e7 1000
e
