# test: contact_types/fig_3_27_edge_edge_fraction
# Thesis Fig 3.27: share of edge-edge among particle-particle contacts (walls and drum not counted)
# for 10 mm cubes at random initial orientations: (a) 216 in a box (polyhedron_packing, random
# velocities up to 0.3 m/s), run until the bed has settled (1.8 s here, 0.9 s in the test), (b) ~220
# in a drum of radius 7 cm from rest, (c) the same drum with all cubes at 1 m/s towards the
# right-hand wall (0.4 s each here, 0.2 s in the test). Linear spring 1e4 N/m, e = 0.3, mu = 0.4,
# dt = t_c/25 = 4.4e-5 s. Two classifications of the same contacts: blue, per step, the kernel's
# kind (axis of least penetration of the separating-axis test); green, sampled every 50 steps on
# the host, the thesis's rule (vertex-face whenever a vertex of either cube is inside the other,
# edge-edge otherwise), which is what Fig 3.27 counts. Dashed: random first touches,
# 9 pi / (24 + 9 pi) = 0.541 (integral geometry); dotted red: the thesis's 10% (a, b) and 30% (c);
# (a) also: the issue's 15% bound and the settled phase (last 25% of the run) where it is asserted
# (pooled over the test's beds of different seeds; the curves show the first bed).
set terminal pngcairo size 1000,700 font ',11'
set output 'plots/fig-3.27.png'
f = datadir.'/fig-3.27.dat'
p_random = 9 * pi / (24 + 9 * pi)
# Index 6, one row: start and end of the settled phase (s), its thesis-rule share over all beds,
# the bound, the lowest and highest bed's share.
stats f index 6 using 1 nooutput
t_settled = STATS_min
stats f index 6 using 2 nooutput
t_end = STATS_min
stats f index 6 using 3 nooutput
settled_share = STATS_min
stats f index 6 using 4 nooutput
bound = STATS_min
set multiplot layout 3,1 title 'Fig 3.27: edge-edge contact frequency of cubes (blaze; blue: least-penetration axis, green: thesis rule)'
set yrange [0:1.35]
set ytics 0, 0.2, 1
set ylabel 'edge-edge share'
set y2label 'contacts'
set y2tics
set y2range [0:*]
set ytics nomirror
set key top right horizontal maxrows 1 font ',9' samplen 2
set lmargin 10
set rmargin 10
titles = "'(a) packing in a box' '(b) drum from rest' '(c) drum, 1 m/s towards the wall'"
thesis = '0.10 0.10 0.30'
thesis_label = "'thesis: at most 10%' 'thesis: slightly above (a)' 'thesis: up to 30%'"
do for [k = 0:2] {
  set title word(titles, k + 1)
  if (k == 2) { set xlabel 't (s)' } else { unset xlabel }
  if (k == 0) {
    set object 1 rect from t_settled, graph 0 to t_end, graph 1 fc rgb '#fff2cc' fs solid 1.0 noborder behind
    set label 1 sprintf('settled phase, all beds: thesis-rule share %.3f (bound %.2f)', settled_share, bound) \
        at t_settled, 0.27 right offset -1, 0 font ',9' tc rgb '#2ca02c'
    plot f index k using 1:($3 > 0 ? $2 : 1/0) with lines lw 1.5 lc rgb '#1f77b4' title 'edge-edge share (SAT axis)', \
         f index k using 1:3 axes x1y2 with lines lw 1 lc rgb '#bbbbbb' title 'contacts (y2)', \
         p_random with lines dt 2 lw 2 lc 'black' title 'random 0.541', \
         word(thesis, k + 1) + 0 with lines dt 3 lw 2 lc rgb '#d62728' title word(thesis_label, k + 1), \
         bound with lines dt 4 lw 2 lc rgb '#ff7f0e' title 'issue bound 15%', \
         f index 3 + k using 1:($3 > 0 ? $2 : 1/0) with lines lw 2 lc rgb '#2ca02c' title 'thesis rule'
    unset object 1
    unset label 1
  } else {
    plot f index k using 1:($3 > 0 ? $2 : 1/0) with lines lw 1.5 lc rgb '#1f77b4' title 'edge-edge share (SAT axis)', \
         f index k using 1:3 axes x1y2 with lines lw 1 lc rgb '#bbbbbb' title 'contacts (y2)', \
         p_random with lines dt 2 lw 2 lc 'black' title 'random 0.541', \
         word(thesis, k + 1) + 0 with lines dt 3 lw 2 lc rgb '#d62728' title word(thesis_label, k + 1), \
         f index 3 + k using 1:($3 > 0 ? $2 : 1/0) with lines lw 2 lc rgb '#2ca02c' title 'thesis rule'
  }
}
unset multiplot
