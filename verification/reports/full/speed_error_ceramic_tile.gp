# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1500,700 enhanced font 'Sans,11'
set output 'speed_error_ceramic_tile.png'
$m0s0 << EOD
4.966553634 56.64045172
0.4386716295 141.8022683
EOD
$m0s1 << EOD
4.966595812 58.2298333
EOD
$m0s2 << EOD
4.964682547 49.96424812
EOD
$m0labels << EOD
4.966553634 56.64045172 "1.5875 mm"
0.4386716295 141.8022683 "1.27 mm"
EOD
$m1s0 << EOD
19.5617171 56.64045172
17.44492018 141.8022683
EOD
$m1s1 << EOD
19.5617171 58.2298333
EOD
$m1s2 << EOD
19.5617171 49.96424812
EOD
$m1labels << EOD
19.5617171 56.64045172 "1.5875 mm"
17.44492018 141.8022683 "1.27 mm"
EOD
set multiplot layout 1,2 title 'Ceramic tile, tungsten rod at 903.9 m/s (cases/ceramic-tile): wall time against |error| (2 threads)' noenhanced
set logscale xy
set grid
set key top right opaque box noenhanced
set xlabel '|error| against the experiment [%]'
set ylabel 'wall time [s]'
set title 'residual velocity (experiment 682 m/s), target 5 %' noenhanced
unset arrow
unset label
set xrange [0.1462238765:15]
set xtics ('0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10)
set yrange [24.98212406:283.6045366]
set ytics ('50' 50, '100' 100, '200' 200)
set arrow 1 from 5, graph 0 to 5, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 5 %' at 5, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m0s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m0s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m0s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m0labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
set title 'residual mass (experiment 6.42 g), target 10 %' noenhanced
unset arrow
unset label
set xrange [3.333333333:58.6851513]
set xtics ('5' 5, '10' 10, '20' 20, '50' 50)
set yrange [24.98212406:283.6045366]
set ytics ('50' 50, '100' 100, '200' 200)
set arrow 1 from 10, graph 0 to 10, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 10 %' at 10, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m1s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m1s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m1s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m1labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
