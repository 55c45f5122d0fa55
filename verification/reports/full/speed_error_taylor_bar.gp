# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1000,700 enhanced font 'Sans,11'
set output 'speed_error_taylor_bar.png'
$m0s0 << EOD
11.90614913 2.273477477
9.517255753 11.00173186
8.199108854 39.34081382
7.627878718 108.3127635
EOD
$m0s1 << EOD
11.90614914 2.813686398
9.517255922 11.0287694
EOD
$m0s2 << EOD
11.9061528 2.463778029
9.51726433 9.872383037
EOD
$m0labels << EOD
11.90614913 2.273477477 "1.27 mm"
9.517255753 11.00173186 "0.8467 mm"
8.199108854 39.34081382 "0.635 mm"
7.627878718 108.3127635 "0.508 mm"
EOD
set multiplot layout 1,1 title 'Taylor bar, OFHC copper at 190 m/s (cases/taylor-bar): wall time against |error| (2 threads)' noenhanced
set logscale xy
set grid
set key top right opaque box noenhanced
set xlabel '|error| against the experiment [%]'
set ylabel 'wall time [s]'
set title 'final length (experiment 16.21 mm), target 3 %' noenhanced
unset arrow
unset label
set xrange [1:35.7184584]
set xtics ('1' 1, '2' 2, '5' 5, '10' 10, '20' 20)
set yrange [1.136738739:216.6255271]
set ytics ('2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100, '200' 200)
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 3 %' at 3, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m0s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m0s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m0s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m0labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
