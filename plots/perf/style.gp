# Shared style of the performance figures (make fig-2.14 ... fig-3.26; tools/perf_figures.py
# writes the data from bench/results).
set terminal pngcairo size 900,600 font ',10'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set key top left font ',9'
set xlabel 'N (bodies)'
set style data linespoints
