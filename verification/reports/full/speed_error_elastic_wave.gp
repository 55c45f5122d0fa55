# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1500,1200 enhanced font 'Sans,11'
set output 'speed_error_elastic_wave.png'
$m0s0 << EOD
0.1093212209 2.830729051
0.02514594729 21.90650055
0.03311779091 35.56980243
0.04696898252 102.8534427
0.05180730056 151.0915144
EOD
$m0s1 << EOD
0.1093212209 5.11441078
0.02514594729 40.3099141
0.03311779091 56.87896847
0.04696898252 122.8931962
EOD
$m0s2 << EOD
0.1081758241 4.461277647
0.02539528452 33.36868119
0.03307300127 47.87268908
0.04660426599 106.5764857
EOD
$m0labels << EOD
0.1093212209 2.830729051 "2 mm"
0.02514594729 21.90650055 "1 mm"
0.03311779091 35.56980243 "0.8 mm"
0.04696898252 102.8534427 "0.5 mm"
0.05180730056 151.0915144 "0.4 mm"
0.1093212209 5.11441078 "2 mm"
0.02514594729 40.3099141 "1 mm"
0.03311779091 56.87896847 "0.8 mm"
EOD
$m1s0 << EOD
0.2292068164 2.830729051
0.3901386767 21.90650055
0.3231408536 35.56980243
0.04763913165 102.8534427
0.02747404613 151.0915144
EOD
$m1s1 << EOD
0.2292068164 5.11441078
0.3901386767 40.3099141
0.3231408536 56.87896847
0.04763913165 122.8931962
EOD
$m1s2 << EOD
0.2298497903 4.461277647
0.3894506804 33.36868119
0.3234463718 47.87268908
0.05735583869 106.5764857
EOD
$m1labels << EOD
0.2292068164 2.830729051 "2 mm"
0.3901386767 21.90650055 "1 mm"
0.3231408536 35.56980243 "0.8 mm"
0.04763913165 102.8534427 "0.5 mm"
0.02747404613 151.0915144 "0.4 mm"
0.2292068164 5.11441078 "2 mm"
0.3901386767 40.3099141 "1 mm"
0.3231408536 56.87896847 "0.8 mm"
EOD
$m2s0 << EOD
26.28905798 2.830729051
16.81283022 21.90650055
14.87873734 35.56980243
11.2195325 102.8534427
9.92351896 151.0915144
EOD
$m2s1 << EOD
26.28905798 5.11441078
16.81283022 40.3099141
14.87873734 56.87896847
11.2195325 122.8931962
EOD
$m2s2 << EOD
26.28622778 4.461277647
16.81108793 33.36868119
14.87921114 47.87268908
11.22236919 106.5764857
EOD
$m2labels << EOD
26.28905798 2.830729051 "2 mm"
16.81283022 21.90650055 "1 mm"
14.87873734 35.56980243 "0.8 mm"
11.2195325 102.8534427 "0.5 mm"
9.92351896 151.0915144 "0.4 mm"
26.28905798 5.11441078 "2 mm"
16.81283022 40.3099141 "1 mm"
14.87873734 56.87896847 "0.8 mm"
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
set yrange [1.415364526:302.1830287]
set ytics ('2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100, '200' 200)
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
set yrange [1.415364526:302.1830287]
set ytics ('2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100, '200' 200)
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
set yrange [1.415364526:302.1830287]
set ytics ('2' 2, '5' 5, '10' 10, '20' 20, '50' 50, '100' 100, '200' 200)
plot $m2s0 u 1:2 w lp pt 7 ps 1.6 lw 1.5 lc rgb '#1f1f1f' t 'reference, double', \
     $m2s1 u 1:2 w lp pt 4 ps 2.2 lw 1.5 lc rgb '#d62728' t 'gpu port host build, double', \
     $m2s2 u 1:2 w lp pt 8 ps 2.2 lw 1.5 lc rgb '#1f77b4' t 'gpu port host build, float', \
     $m2labels u 1:2:3 w labels offset 0.8,0.8 left font ',9' notitle
unset multiplot
unset output
