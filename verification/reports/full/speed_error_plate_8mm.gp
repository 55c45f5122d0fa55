# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1000,700 enhanced font 'Sans,11'
set output 'speed_error_plate_8mm.png'
$m0s0 << EOD
6.192438941 1.523947433
0.7724694415 30.59553625
0.07775731487 64.06930481
0.1226318036 134.1920059
EOD
$m0s1 << EOD
6.192438941 1.648986865
0.7724694415 32.2669651
EOD
$m0s2 << EOD
6.192441794 1.464270632
0.772080652 27.4429859
EOD
$m0labels << EOD
6.192438941 1.523947433 "4 mm"
0.7724694415 30.59553625 "2 mm"
0.07775731487 64.06930481 "1.6 mm"
0.1226318036 134.1920059 "1.3333 mm"
EOD
set multiplot layout 1,1 title '8 mm Weldox 460 E plate at 298 m/s (cases/plate-8mm): wall time against |error| (2 threads)' noenhanced
set logscale xy
set grid
set key top right opaque box noenhanced
set xlabel '|error| against the experiment [%]'
set ylabel 'wall time [s]'
set title 'residual velocity (experiment 232.7 m/s), target 10 %' noenhanced
unset arrow
unset label
set xrange [0.02591910496:30]
set xtics ('0.05' 0.05, '0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20)
set yrange [0.732135316:268.3840118]
set ytics ('1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100, '200' 200)
set arrow 1 from 10, graph 0 to 10, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 10 %' at 10, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m0s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m0s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m0s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m0labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
