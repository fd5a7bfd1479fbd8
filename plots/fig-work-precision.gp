# test: (study) make fig-work-precision runs build/<backend>/study_work_precision
# Error against wall time for the drag fall, the damped head-on collision and the falling spheres'
# energy, across dt: float/double x Euler/Verlet (and the half-step Verlet), CPU and (when its
# results are committed) GPU. Points down and to the left are better; the Pareto front is listed in
# verification/README.md.
set terminal pngcairo size 1500,520 font ',10'
set output 'plots/fig-work-precision.png'
set multiplot layout 1,3 title 'Work-precision: error vs wall time (filled: CPU, open: GPU)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'wall time (s)'
set ylabel 'error'
set key bottom left font ',8'
cpu = 'verification/results/work_precision_cpu.dat'
gpu = 'verification/results/work_precision_gpu.dat'
have_gpu = system('[ -f '.gpu.' ] && echo 1 || echo 0') + 0
names = 'float-Euler float-Verlet double-Euler double-Verlet double-half-step'
do for [c = 0:2] {
  if (c == 0) { set title 'drag fall: max relative error of x, v' }
  if (c == 1) { set title 'head-on, Hertz e = 0.5: |e_{out}/e - 1|' }
  if (c == 2) { set title 'falling spheres, 1 s: max relative energy drift' }
  if (have_gpu) {
    plot for [s = 0:4] cpu index (5*c + s) using 3:2 with linespoints pt 7 lc (s+1) title word(names, s+1).' cpu', \
         for [s = 0:4] gpu index (5*c + s) using 3:2 with linespoints pt 6 dt 2 lc (s+1) title word(names, s+1).' gpu'
  } else {
    plot for [s = 0:4] cpu index (5*c + s) using 3:2 with linespoints pt 7 lc (s+1) title word(names, s+1)
  }
}
unset multiplot
