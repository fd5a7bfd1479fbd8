# Angle of repose of glass beads against the rolling friction mu_r, one line per sliding friction
# mu_s (make fig-repose; studies/repose/main.cpp): Blaze (filled) and LIGGGHTS (open) on the same
# poured pile, from <dir>/angles.csv; the band is the measured range for glass-bead heaps.
# A LIGGGHTS series with no angle in angles.csv is left out (gnuplot warns that it has no points).
#   gnuplot -e "dir='data/repose'; size='small'" plots/repose.gp       -> plots/fig-repose.png
#   gnuplot -e "dir='data/repose/full'; size='full'" plots/repose.gp  -> plots/fig-repose-full.png
if (!exists("dir")) dir = 'data/repose'
if (!exists("size")) size = 'small'
set terminal pngcairo size 900,650 font ',11'
set output (size eq 'full' ? 'plots/fig-repose-full.png' : 'plots/fig-repose.png')
set datafile separator ','
f = dir.'/angles.csv'
set title 'Angle of repose of 3 mm glass beads: fixed-base pile (Hertz-Mindlin + rolling model C)'
set xlabel 'rolling friction {/Symbol m}_r'
set ylabel 'angle of repose (deg)'
set xrange [-0.01:0.11]
set yrange [0:45]
set grid
set key top right font ',9'
set object 1 rect from graph 0, first 22 to graph 1, first 26 fc rgb '#e0e0e0' fs solid 0.6 noborder behind
set label 1 'glass beads, measured heaps: 22-26 deg' at graph 0.02, first 24 font ',9'
near(x, y) = abs(x - y) < 1e-6
mus = '0.2 0.4 0.6'
blaze(k) = sprintf('Blaze {/Symbol m}_s = %s', word(mus, k))
# more: other realisations' angles.csv files (make repose-scatter: the fill's gap changed), small crosses
if (!exists("more")) more = ''
liggghts(k) = 'LIGGGHTS {/Symbol m}_s = '.word(mus, k)
other(m, k) = (k == 1 && m == 1) ? 'Blaze, other starts (make repose-scatter)' : ''
# (LIGGGHTS's points where angles.csv has them: a column with none only warns)
# (angles.csv's columns: 2 mu_s, 3 mu_r, 4 Blaze's angle, 9 LIGGGHTS's)
if (more eq '') {
  plot for [k = 1:3] f skip 1 using 3:(near($2, word(mus, k) + 0) ? $4 : 1/0) smooth unique with linespoints lw 2 pt 7 lc k \
         title blaze(k), \
       for [k = 1:3] f skip 1 using 3:(near($2, word(mus, k) + 0) ? $9 : 1/0) with points pt 6 ps 2 lc k title liggghts(k)
} else {
  plot for [k = 1:3] f skip 1 using 3:(near($2, word(mus, k) + 0) ? $4 : 1/0) smooth unique with linespoints lw 2 pt 7 lc k \
         title blaze(k), \
       for [k = 1:3] f skip 1 using 3:(near($2, word(mus, k) + 0) ? $9 : 1/0) with points pt 6 ps 2 lc k title liggghts(k), \
       for [m = 1:words(more)] for [k = 1:3] word(more, m) skip 1 using 3:(near($2, word(mus, k) + 0) ? $4 : 1/0) \
         with points pt 2 ps 1.2 lc k title other(m, k)
}
