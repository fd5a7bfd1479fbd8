# make fig-mill-work-precision: the lab mill's power error against wall time, each law and
# precision a line through dt = t_c/10 ... t_c/100 (tools/mill_work_precision.sh).
if (!exists("csv")) csv = 'data/mill/work_precision/work_precision.csv'
set terminal pngcairo size 1000,450 font ",11"
set output 'plots/fig-mill-work-precision.png'
set datafile separator ','
set multiplot layout 1,2 title 'Lab mill, 30% filling, 22 rpm: error against wall time (reference: double, dt = t_c/200)'
set logscale x
set xlabel 'wall time of 5 revolutions (s)'
set key top right
sel(law, prec, col) = (strcol(1) eq law && strcol(2) eq prec) ? column(col) : NaN
set ylabel 'power error (%)'
set logscale y
plot csv skip 1 using 8:(sel('history_free', 'double', 9)) with linespoints pt 7 lc rgb 'royalblue' title 'history-free, double', \
     csv skip 1 using 8:(sel('history_free', 'float', 9)) with linespoints pt 6 dt 2 lc rgb 'royalblue' title 'history-free, float', \
     csv skip 1 using 8:(sel('hertz_mindlin', 'double', 9)) with linespoints pt 5 lc rgb 'orange-red' title 'Hertz-Mindlin, double', \
     csv skip 1 using 8:(sel('hertz_mindlin', 'float', 9)) with linespoints pt 4 dt 2 lc rgb 'orange-red' title 'Hertz-Mindlin, float'
set ylabel 'toe angle error (deg)'
unset logscale y
plot csv skip 1 using 8:(sel('history_free', 'double', 10)) with linespoints pt 7 lc rgb 'royalblue' title 'history-free, double', \
     csv skip 1 using 8:(sel('history_free', 'float', 10)) with linespoints pt 6 dt 2 lc rgb 'royalblue' title 'history-free, float', \
     csv skip 1 using 8:(sel('hertz_mindlin', 'double', 10)) with linespoints pt 5 lc rgb 'orange-red' title 'Hertz-Mindlin, double', \
     csv skip 1 using 8:(sel('hertz_mindlin', 'float', 10)) with linespoints pt 4 dt 2 lc rgb 'orange-red' title 'Hertz-Mindlin, float'
unset multiplot
