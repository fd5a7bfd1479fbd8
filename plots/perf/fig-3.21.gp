# make fig-3.21: thesis Fig 3.21, polyhedron-world contact against the number of world surfaces
# (K6000; no values in its text, "linear scaling"). Ours: the world phase (CUDA events) of a packed
# bed of 1e6 bodies in a box whose floor is split into 1, 4, 16, 64, 256 polygons; and (issue 20)
# the same with meshes: packed cubes on a floor of 1e3-1e5 triangles, the dense sphere bed in a box
# of 1e3-1e6 triangles (each particle tests the triangles in its reach: nearly flat in the count).
# The mesh series come from blaze_bench --cases mesh on one device, each with its own 6-polygon point
# (the cubes there evaluate each pair once and lie in another bed): compare within a series.
load 'plots/perf/style.gp'
set output 'plots/perf/fig-3.21.png'
set title 'Fig 3.21: world contact vs world surfaces (thesis: K6000, no values given, "linear")'
set xlabel 'world surfaces (polygons or triangles)'
set ylabel 'ms per step (world contact)'
data = 'plots/perf/data/fig-3.21.dat'
plot for [i=0:3] data index i u 1:2 title columnheader(1)
