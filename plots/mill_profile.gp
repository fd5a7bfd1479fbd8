# The time-averaged charge of mill runs (study_mill's charge_field.csv; include/blaze/sim/
# charge_field.hpp) as the thesis's profile figures show it: the drum seen along its axis, each cell
# coloured by the mean number of ball centres in it, arrows for the mean velocity, the shell, and
# rays to the mean toe and shoulder (charge_profile.hpp; measured from the bottom in the direction
# of rotation). Called by tools/mill_2d.sh and tools/table_4_4.sh with
#   n (panels), cols, out (PNG), R (shell radius, m), h (cell, m), vs (arrow length per m/s, m),
#   every (an arrow every this many cells),
#   and per panel k = 1..n: file<k>, title<k>, toe<k>, shoulder<k> (deg), sign<k> (+1: the drum
#   turns counter-clockwise in the picture)
set terminal pngcairo size 520*cols, 540*int((n + cols - 1) / cols) font ",10"
set output out
set datafile separator ','
set size ratio -1
unset key
set xrange [-1.08*R:1.08*R]
set yrange [-1.08*R:1.08*R]
set xlabel 'm'
set ylabel 'm'
set cblabel 'ball centres per cell'
set palette defined (0 'white', 0.1 '#c6dbef', 0.5 '#4292c6', 1 '#08306b')
set cbrange [0:*]
rows = int((n + cols - 1) / cols)
set multiplot layout rows, cols
do for [k=1:n] {
  f = value(sprintf('file%d', k))
  set title value(sprintf('title%d', k)) noenhanced
  t = value(sprintf('toe%d', k)) * pi / 180
  s = value(sprintf('shoulder%d', k)) * pi / 180
  g = value(sprintf('sign%d', k))
  set object 1 circle at 0,0 size R front fillstyle empty border lc rgb 'black' lw 1.5
  set arrow 1 from 0,0 to g*R*sin(t), -R*cos(t) front nohead lc rgb 'dark-orange' lw 2 dt 2
  set arrow 2 from 0,0 to g*R*sin(s), -R*cos(s) front nohead lc rgb 'dark-red' lw 2 dt 2
  set label 1 'toe' at g*1.04*R*sin(t), -1.04*R*cos(t) center front tc rgb 'dark-orange'
  set label 2 'shoulder' at g*1.04*R*sin(s), -1.04*R*cos(s) center front tc rgb 'dark-red'
  even(u, w) = (int(floor((u + R) / h)) % every == 0 && int(floor((w + R) / h)) % every == 0)
  plot f skip 1 using 1:2:3 with points pt 5 ps 520.0 / (2*R/h) / 7 lc palette, \
       f skip 1 using 1:2:((even($1, $2) && $3 > 0.05) ? $4*vs : NaN):($5*vs) with vectors head size 0.01*R,20 filled lc rgb 'black' lw 0.7
}
unset multiplot
