# make fig-slice-mill: the slice mill's power against speed (% of critical) for 25% and 35%
# filling (thesis Fig. 4.13), and the centrifuging balls. csv: data/mill/slice/power.csv.
if (!exists("csv")) csv = 'data/mill/slice/power.csv'
set terminal pngcairo size 900,600 font ",11"
set output 'plots/fig-slice-mill.png'
set datafile separator ','
set key top left
set xlabel 'mill speed (% of critical)'
set ylabel 'power (W)'
set y2label 'balls centrifuging'
set ytics nomirror
set y2tics
set title 'Slice mill (thesis section 4.2.2): power draw and centrifuging balls'
set xrange [20:170]
sel(fill, col) = (int(column(1)) == fill) ? column(col) : NaN
plot for [f in "25 35"] csv skip 1 using 3:(sel(int(f), 4)) with linespoints pt 7 lw 2 title 'torque method, '.f.'%', \
     for [f in "25 35"] csv skip 1 using 3:(sel(int(f), 5)) with points pt 6 ps 2 title 'energy method, '.f.'%', \
     for [f in "25 35"] csv skip 1 using 3:(sel(int(f), 6)) axes x1y2 with linespoints dt 2 pt 4 title 'centrifuging balls, '.f.'%'
