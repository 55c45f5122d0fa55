# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1500,1200 enhanced font 'Sans,11'
set output 'speed_error_hugoniot.png'
$m0s0 << EOD
0.4781294538 0.125827289
0.4648306268 1.852418441
0.04557603408 28.78271788
0.03284538108 65.88770506
EOD
$m0labels << EOD
0.4781294538 0.125827289 "0.5 mm"
0.4648306268 1.852418441 "0.25 mm"
0.04557603408 28.78271788 "0.125 mm"
0.03284538108 65.88770506 "0.1 mm"
EOD
$m1s0 << EOD
3.847876599 0.125827289
1.765394576 1.852418441
1.133066322 28.78271788
0.06766609421 65.88770506
EOD
$m1labels << EOD
3.847876599 0.125827289 "0.5 mm"
1.765394576 1.852418441 "0.25 mm"
1.133066322 28.78271788 "0.125 mm"
0.06766609421 65.88770506 "0.1 mm"
EOD
$m2s0 << EOD
0.8956842748 0.13035979
0.492459203 2.060279257
0.06685533442 29.05936687
0.04488257522 66.61470186
EOD
$m2labels << EOD
0.8956842748 0.13035979 "0.5 mm"
0.492459203 2.060279257 "0.25 mm"
0.06685533442 29.05936687 "0.125 mm"
0.04488257522 66.61470186 "0.1 mm"
EOD
$m3s0 << EOD
3.833844143 0.13035979
1.824278613 2.060279257
0.1530970018 29.05936687
0.3792886127 66.61470186
EOD
$m3labels << EOD
3.833844143 0.13035979 "0.5 mm"
1.824278613 2.060279257 "0.25 mm"
0.1530970018 29.05936687 "0.125 mm"
0.3792886127 66.61470186 "0.1 mm"
EOD
set multiplot layout 2,2 title 'Hugoniot, 4340 steel (cases/hugoniot-4340): wall time against |error| (2 threads)' noenhanced
set logscale xy
set grid
set key top right opaque box noenhanced
set xlabel '|error| against the closed form [%]'
set ylabel 'wall time [s]'
set title '500 m/s: shock pressure, target 3 %' noenhanced
unset arrow
unset label
set xrange [0.01094846036:9]
set xtics ('0.02' 0.02, '0.05' 0.05, '0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5)
set yrange [0.0629136445:131.7754101]
set ytics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100)
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 3 %' at 3, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m0s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m0labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
set title '500 m/s: shock speed, target 3 %' noenhanced
unset arrow
unset label
set xrange [0.02255536474:11.5436298]
set xtics ('0.05' 0.05, '0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10)
set yrange [0.0629136445:131.7754101]
set ytics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100)
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 3 %' at 3, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m1s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m1labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
set title '1000 m/s: shock pressure, target 3 %' noenhanced
unset arrow
unset label
set xrange [0.01496085841:9]
set xtics ('0.02' 0.02, '0.05' 0.05, '0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5)
set yrange [0.065179895:133.2294037]
set ytics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100)
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 3 %' at 3, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m2s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m2labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
set title '1000 m/s: shock speed, target 3 %' noenhanced
unset arrow
unset label
set xrange [0.05103233393:11.50153243]
set xtics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10)
set yrange [0.065179895:133.2294037]
set ytics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100)
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 3 %' at 3, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m3s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m3labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
