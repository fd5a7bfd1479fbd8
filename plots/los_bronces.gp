# make los-bronces: the SAG mill's power per revolution (torque and energy method) and its
# dissipation by contact class, against the plant's 7.1 MW and the thesis's 6.8 MW (thesis Fig 4.20).
# csv: data/mill/los_bronces/power.csv (study_mill).
if (!exists("csv")) csv = 'data/mill/los_bronces/power.csv'
set terminal pngcairo size 900,600 font ",11"
set output 'plots/fig-los-bronces.png'
set datafile separator ','
set key outside right
set xlabel 'revolution'
set ylabel 'power (MW)'
set title 'Los Bronces SAG mill (thesis section 4.3): power draw by revolution'
set yrange [0:*]
plot csv skip 1 using 1:($3/1e6) with linespoints pt 7 lw 2 title 'torque method', \
     csv skip 1 using 1:($4/1e6) with points pt 6 ps 2 title 'energy method', \
     csv skip 1 using 1:($8/1e6) with linespoints dt 2 title 'particle-lifter', \
     csv skip 1 using 1:($7/1e6) with linespoints dt 2 title 'particle-shell', \
     csv skip 1 using 1:($6/1e6) with linespoints dt 2 title 'particle-particle', \
     7.1 with lines lw 2 lc rgb 'black' title 'plant 7.1 MW', \
     6.8 with lines dt 3 lc rgb 'gray40' title 'thesis 6.8 MW'
