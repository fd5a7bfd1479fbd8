# make table-4.4: the lab mill's power against speed (thesis Table 4.4): experiment, the thesis's
# GPU DEM and Blaze with both laws, for 20% and 30% filling. csv: data/mill/table-4.4/power.csv.
if (!exists("csv")) csv = 'data/mill/table-4.4/power.csv'
set terminal pngcairo size 900,600 font ",11"
set output 'plots/fig-mill-power.png'
set datafile separator ','
set key top left
set xlabel 'mill speed (rpm)'
set ylabel 'power (W)'
set title 'Lab mill (Venugopal and Rajamani; thesis Table 4.4): power draw, e = 0.825, mu = 0.15'
set xrange [10:36]
set yrange [0:700]
sel(law, fill, col) = (strcol(1) eq law && int(column(2)) == fill) ? column(col) : NaN
experiment(fill) = (strcol(1) eq 'history_free' && int(column(2)) == fill) ? column(4) : NaN
thesis(fill) = (strcol(1) eq 'history_free' && int(column(2)) == fill) ? column(5) : NaN
plot for [f in "20 30"] csv skip 1 using 3:(experiment(int(f))) with linespoints pt 7 ps 1.3 lc rgb 'black' title 'experiment, '.f.'%', \
     for [f in "20 30"] csv skip 1 using 3:(thesis(int(f))) with linespoints pt 6 ps 1.3 dt 2 lc rgb 'gray40' title 'thesis GPU, '.f.'%', \
     for [f in "20 30"] csv skip 1 using 3:(sel('history_free', int(f), 6)) with linespoints pt 5 lc rgb 'royalblue' title 'Blaze history-free, '.f.'%', \
     for [f in "20 30"] csv skip 1 using 3:(sel('hertz_mindlin', int(f), 6)) with linespoints pt 9 lc rgb 'orange-red' title 'Blaze Hertz-Mindlin, '.f.'%'
