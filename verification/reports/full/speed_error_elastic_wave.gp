# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1500,1200 enhanced font 'Sans,11'
set output 'speed_error_elastic_wave.png'
$m0s0 << EOD
0.1093212209 0.24023203
0.02514594729 2.550638527
0.03311779091 6.46099081
0.04696898252 37.88631868
0.05180730056 92.10717101
EOD
$m0s1 << EOD
0.1093212209 0.20936771
0.02514594729 2.633622558
0.03311779091 6.922126808
0.04696898252 41.84819507
EOD
$m0s2 << EOD
0.1081743766 0.177153731
0.02516854801 2.248783602
0.03307359189 5.724536599
0.04669238528 33.81853028
EOD
$m0labels << EOD
0.1093212209 0.24023203 "2 mm"
0.02514594729 2.550638527 "1 mm"
0.03311779091 6.46099081 "0.8 mm"
0.04696898252 37.88631868 "0.5 mm"
0.05180730056 92.10717101 "0.4 mm"
EOD
$m1s0 << EOD
0.2292068164 0.24023203
0.3901386767 2.550638527
0.3231408536 6.46099081
0.04763913165 37.88631868
0.02747404613 92.10717101
EOD
$m1s1 << EOD
0.2292068164 0.20936771
0.3901386767 2.633622558
0.3231408536 6.922126808
0.04763913165 41.84819507
EOD
$m1s2 << EOD
0.2298490438 0.177153731
0.3896926745 2.248783602
0.3224381736 5.724536599
0.05682975064 33.81853028
EOD
$m1labels << EOD
0.2292068164 0.24023203 "2 mm"
0.3901386767 2.550638527 "1 mm"
0.3231408536 6.46099081 "0.8 mm"
0.04763913165 37.88631868 "0.5 mm"
0.02747404613 92.10717101 "0.4 mm"
EOD
$m2s0 << EOD
26.28905798 0.24023203
16.81283022 2.550638527
14.87873734 6.46099081
11.2195325 37.88631868
9.92351896 92.10717101
EOD
$m2s1 << EOD
26.28905798 0.20936771
16.81283022 2.633622558
14.87873734 6.922126808
11.2195325 41.84819507
EOD
$m2s2 << EOD
26.28683203 0.177153731
16.81216017 2.248783602
14.8785134 5.724536599
11.22110584 33.81853028
EOD
$m2labels << EOD
26.28905798 0.24023203 "2 mm"
16.81283022 2.550638527 "1 mm"
14.87873734 6.46099081 "0.8 mm"
11.2195325 37.88631868 "0.5 mm"
9.92351896 92.10717101 "0.4 mm"
EOD
set multiplot layout 2,2 title 'Elastic wave (cases/elastic-wave-convergence): wall time against |error| (2 threads)' noenhanced
set logscale xy
set grid
set key top right opaque box noenhanced
set xlabel '|error| against the closed form [%]'
set ylabel 'wall time [s]'
set title 'wave speed (c_L), target 1 %' noenhanced
unset arrow
unset label
set xrange [0.008381982431:3]
set xtics ('0.01' 0.01, '0.02' 0.02, '0.05' 0.05, '0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2)
set yrange [0.0885768655:184.214342]
set ytics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100)
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 1 %' at 1, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m0s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m0s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m0s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m0labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
set title 'stress amplitude (rho c_L v), target 3 %' noenhanced
unset arrow
unset label
set xrange [0.009158015377:9]
set xtics ('0.01' 0.01, '0.02' 0.02, '0.05' 0.05, '0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5)
set yrange [0.0885768655:184.214342]
set ytics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100)
set arrow 1 from 3, graph 0 to 3, graph 1 nohead dt 2 lw 2 lc rgb '#7f7f7f'
set label 1 'target 3 %' at 3, graph 0.04 offset 0.5,0 left tc rgb '#555555'
plot $m1s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m1s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m1s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m1labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
set title 'velocity profile L1, no target' noenhanced
unset arrow
unset label
set xrange [3.307839653:78.86717394]
set xtics ('5' 5, '10' 10, '20' 20, '50' 50)
set yrange [0.0885768655:184.214342]
set ytics ('0.1' 0.1, '0.2' 0.2, '0.5' 0.5, '1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100)
plot $m2s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m2s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m2s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m2labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
