# make fig-2.15 / fig-2.16 (tools/hopper_pizette.sh): the hopper of thesis section 2.5.3.
#   gnuplot -e "dir='data/hopper/pizette'" plots/hopper_pizette.gp
# fig-2.15: the beds as the gate opens, in alternating layers of 250 particles as poured (the
# thesis's experiment packs alternating colours), with the hopper's outline.
# fig-2.16: discharged mass against time for every run; where each particle started, coloured by
# the time it left (grey: it never left) for the first seed of each shape.
if (!exists("dir")) dir = 'data/hopper/pizette'
set datafile separator ','
spheres = system("ls -d ".dir."/spheres_s* 2>/dev/null | grep -v log")
dodecas = system("ls -d ".dir."/dodecahedra_s* 2>/dev/null | grep -v log")
first_s = word(spheres, 1)
first_d = word(dodecas, 1)
set style line 1 lc rgb '#1f77b4' lw 2
set style line 2 lc rgb '#d62728' lw 2
outline = "set arrow 1 from -0.08,0 to -0.025,0 nohead lw 3; set arrow 2 from 0.025,0 to 0.08,0 nohead lw 3; " . \
          "set arrow 3 from -0.08,0 to -0.08,0.25 nohead lw 3; set arrow 4 from 0.08,0 to 0.08,0.25 nohead lw 3"

set terminal pngcairo size 1100,650 font ',11'
set output 'plots/fig-2.15.png'
set multiplot layout 1,2 title "Fig 2.15: the beds at the gate's opening, poured down the centre (layers of 250 in alternating colours)"
set size ratio -1
set xrange [-0.09:0.09]
set yrange [-0.01:0.25]
set xlabel 'x (m)'
set ylabel 'y (m)'
unset colorbox
set palette defined (0 '#f0a030', 1 '#3050c0')
set cbrange [0:1]
eval outline
set title '2000 spheres (d = 10 mm)'
plot first_s.'/discharge.csv' skip 1 using 2:3:(int($1/250)%2) with points pt 7 ps 0.45 lc palette notitle
set title '2000 dodecahedra (same volume)'
plot first_d.'/discharge.csv' skip 1 using 2:3:(int($1/250)%2) with points pt 7 ps 0.45 lc palette notitle
unset multiplot
unset arrow

set output 'plots/fig-2.16.png'
set terminal pngcairo size 1500,600 font ',11'
set multiplot layout 1,3 title "Fig 2.16: discharge of 2000 spheres and 2000 dodecahedra (mu_{pp} 0.35, mu_{wall} 0.30, e 0.4)"
set size noratio
set autoscale
set xrange [0:4.5]
set yrange [0:*]
set key top left
set grid
set xlabel 't after the gate opens (s)'
set ylabel 'discharged mass (kg)'
set title '(a) discharge curves (every seed)'
plot for [d in spheres] d.'/timeseries.csv' skip 1 using 1:2 with lines ls 1 title (d eq first_s ? 'spheres' : ''), \
     for [d in dodecas] d.'/timeseries.csv' skip 1 using 1:2 with lines ls 2 title (d eq first_d ? 'dodecahedra' : '')
unset grid
set size ratio -1
set xrange [-0.09:0.09]
set yrange [-0.01:0.25]
set xlabel 'x at the opening (m)'
set ylabel 'y at the opening (m)'
set colorbox
set cblabel 'exit time (s)'
set palette rgbformulae 33,13,10
set cbrange [0:4.5]
eval outline
set title '(b) spheres: where the particles started, by exit time'
plot first_s.'/discharge.csv' skip 1 using 2:3:(valid(5) ? 1/0 : 0) with points pt 7 ps 0.45 lc rgb '#bbbbbb' notitle, \
     '' skip 1 using 2:3:5 with points pt 7 ps 0.45 lc palette notitle
set title '(c) dodecahedra'
plot first_d.'/discharge.csv' skip 1 using 2:3:(valid(5) ? 1/0 : 0) with points pt 7 ps 0.45 lc rgb '#bbbbbb' notitle, \
     '' skip 1 using 2:3:5 with points pt 7 ps 0.45 lc palette notitle
unset multiplot
