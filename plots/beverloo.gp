# Beverloo's law: the silo's mass flow rate against the orifice (make fig-beverloo, tools/beverloo.sh)
#   gnuplot -e "summary='data/silo/beverloo/summary.csv'" plots/beverloo.gp
if (!exists("summary")) summary = 'data/silo/beverloo/summary.csv'
fit_line = system("head -1 ".summary)
C = real(word(fit_line, 6)); k = real(word(fit_line, 9)); rho = real(word(fit_line, 12)); d = real(word(fit_line, 16))
set terminal pngcairo size 900,650 font ',11'
set output 'plots/fig-beverloo.png'
set datafile separator ','
set key top left
set grid
set xlabel 'orifice diameter D (mm)'
set ylabel 'mass flow rate W (kg/s)'
law = system("head -1 ".summary." | sed -n 's/.* law = //p'")
set title sprintf("Beverloo's law in a flat-bottomed silo, d = %g mm glass beads, %s", 1000*d, law) noenhanced
W(D, c, kk) = D > kk*d ? c * rho * sqrt(9.81) * (D - kk*d)**2.5 : 0
set xrange [0:70]
set samples 200
plot summary skip 2 using (1000*$1):3 with points pt 7 ps 1.5 lc rgb '#c0392b' title 'Blaze (steady rate of each run)', \
     W(x/1000, C, k) with lines lw 2 lc rgb '#2c3e50' title sprintf('fit: C = %.3f, k = %.2f', C, k), \
     W(x/1000, 0.58, 1.4) with lines lw 2 dt 2 lc rgb '#7f8c8d' title 'Beverloo et al. 1961: C = 0.58, k = 1.4'
