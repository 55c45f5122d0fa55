# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1000,700 enhanced font 'Sans,11'
set output 'speed_error_plate_8mm.png'
$m0s0 << EOD
6.192438941 1.218887116
0.7724694415 23.61966374
0.07775731487 57.93567374
0.1226318036 108.938119
EOD
$m0s1 << EOD
6.192438941 1.184907162
0.7724694415 26.6072841
EOD
$m0s2 << EOD
6.192441794 0.939804748
0.772080652 20.88967016
EOD
$m0labels << EOD
6.192438941 1.218887116 "4 mm"
0.7724694415 23.61966374 "2 mm"
0.07775731487 57.93567374 "1.6 mm"
0.1226318036 108.938119 "1.3333 mm"
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
set yrange [0.469902374:217.876238]
set ytics ('0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100, '200' 200)
set arrow 1 from 10, graph 0 to 10, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 10 %' at 10, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m0s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m0s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m0s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m0labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
