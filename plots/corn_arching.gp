# Corn kernels arching in a hopper (make fig-2.17, tools/corn_arching.sh): per orifice, the share
# of runs that arched and the share of the kernels that left
#   gnuplot -e "dir='data/hopper/corn'" plots/corn_arching.gp
if (!exists("dir")) dir = 'data/hopper/corn'
set terminal pngcairo size 900,650 font ',11'
set output 'plots/fig-2.17.png'
set datafile separator ','
set key top right
set grid
set xlabel 'orifice side / kernel length (W / 11 mm)'
set ylabel 'share'
set yrange [0:1.05]
set offsets 0.25, 0.25, 0, 0
set title 'corn kernels in a 60-degree hopper (studies/hopper/corn.toml): arching against the orifice' noenhanced
plot dir.'/summary_by_orifice.csv' skip 1 using 2:5 with linespoints pt 7 ps 1.5 lw 2 lc rgb '#c0392b' title 'runs that arched', \
     dir.'/summary_by_orifice.csv' skip 1 using 2:6 with linespoints pt 5 ps 1.3 lw 2 lc rgb '#2c3e50' title 'kernels discharged (mean)', \
     dir.'/summary.csv' skip 1 using 2:($5/$4) with points pt 6 ps 1 lc rgb '#7f8c8d' title 'kernels discharged (each run)'
