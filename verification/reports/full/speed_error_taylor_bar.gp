# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1000,700 enhanced font 'Sans,11'
set output 'speed_error_taylor_bar.png'
$m0s0 << EOD
20.18790403 1.3933681
17.35194017 4.625461192
14.99114421 16.81185986
13.44725973 46.42463309
EOD
$m0s1 << EOD
20.18790409 1.293648622
17.35194016 4.326466426
EOD
$m0s2 << EOD
20.1878779 1.332499473
17.35190201 3.888961557
EOD
$m0labels << EOD
20.18790403 1.3933681 "1.27 mm"
17.35194017 4.625461192 "0.8467 mm"
14.99114421 16.81185986 "0.635 mm"
13.44725973 46.42463309 "0.508 mm"
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
set xrange [1:60.56371228]
set xtics ('1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50)
set yrange [0.646824311:92.84926619]
set ytics ('1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50)
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 3 %' at 3, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m0s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m0s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m0s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m0labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
