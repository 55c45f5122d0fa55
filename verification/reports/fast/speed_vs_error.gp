# Drawn by impactsph verify; to redraw, run gnuplot on this file from the folder verify ran in (the
# output path below is relative to it).
set terminal pngcairo size 1000,750 enhanced font 'Sans,11'
set output 'verification/reports/fast/speed_vs_error.png'
set title 'Speed against error: reference and gpu port, 1 thread(s)' noenhanced
set xlabel '|relative error|'
set ylabel 'wall time [s]'
set grid
set key below left Left reverse noenhanced
set logscale xy
set format x '10^{%L}'
$w0 << EOD
0.2628905798 0.216665559
0.1681283022 3.106098769
0.1487873734 7.363437028
0.112195325 48.08367445
EOD
$w1 << EOD
0.001093212209 0.216665559
0.0002514594729 3.106098769
0.0003311779091 7.363437028
0.0004696898252 48.08367445
EOD
$w2 << EOD
0.002292068164 0.216665559
0.003901386767 3.106098769
0.003231408536 7.363437028
0.0004763913165 48.08367445
EOD
$w3 << EOD
0.2628905798 0.215557102
0.1681283022 3.076837344
0.1487873734 7.30493891
EOD
$w4 << EOD
0.001093212209 0.215557102
0.0002514594729 3.076837344
0.0003311779091 7.30493891
EOD
$w5 << EOD
0.002292068164 0.215557102
0.003901386767 3.076837344
0.003231408536 7.30493891
EOD
$w6 << EOD
0.2628704017 0.206837325
0.1681111861 2.959066663
0.1487928939 7.023463968
EOD
$w7 << EOD
0.001081850446 0.206837325
0.0002538408917 2.959066663
0.0003307402279 7.023463968
EOD
$w8 << EOD
0.002299430092 0.206837325
0.00390429884 2.959066663
0.003231872747 7.023463968
EOD
$w9 << EOD
0.004781294538 0.136786412
0.004648306268 2.128882902
0.0004557603408 35.0442611
0.0003284538108 86.67781985
EOD
$w10 << EOD
0.03847876599 0.136786412
0.01765394576 2.128882902
0.01133066322 35.0442611
0.0006766609421 86.67781985
EOD
$w11 << EOD
0.008956842748 0.144753046
0.00492459203 2.333612359
0.0006685533442 38.18110543
0.0004488257522 94.06587978
EOD
$w12 << EOD
0.03833844143 0.144753046
0.01824278613 2.333612359
0.001530970018 38.18110543
0.003792886127 94.06587978
EOD
plot $w0 u 1:2 w lp pt 7 ps 1.4 dt 1 lc rgb '#1f77b4' t 'elastic wave: velocity profile L1 (reference, double)', \
     $w1 u 1:2 w lp pt 7 ps 1.4 dt 1 lc rgb '#d62728' t 'elastic wave: wave speed (reference, double)', \
     $w2 u 1:2 w lp pt 7 ps 1.4 dt 1 lc rgb '#2ca02c' t 'elastic wave: stress amplitude (reference, double)', \
     $w3 u 1:2 w lp pt 5 ps 1.4 dt 2 lc rgb '#1f77b4' t 'elastic wave: velocity profile L1 (gpu port host build, double)', \
     $w4 u 1:2 w lp pt 5 ps 1.4 dt 2 lc rgb '#d62728' t 'elastic wave: wave speed (gpu port host build, double)', \
     $w5 u 1:2 w lp pt 5 ps 1.4 dt 2 lc rgb '#2ca02c' t 'elastic wave: stress amplitude (gpu port host build, double)', \
     $w6 u 1:2 w lp pt 9 ps 1.4 dt 3 lc rgb '#1f77b4' t 'elastic wave: velocity profile L1 (gpu port host build, float)', \
     $w7 u 1:2 w lp pt 9 ps 1.4 dt 3 lc rgb '#d62728' t 'elastic wave: wave speed (gpu port host build, float)', \
     $w8 u 1:2 w lp pt 9 ps 1.4 dt 3 lc rgb '#2ca02c' t 'elastic wave: stress amplitude (gpu port host build, float)', \
     $w9 u 1:2 w lp pt 7 ps 1.4 dt 1 lc rgb '#ff7f0e' t 'Hugoniot 500 m/s: shock pressure (reference, double)', \
     $w10 u 1:2 w lp pt 7 ps 1.4 dt 1 lc rgb '#9467bd' t 'Hugoniot 500 m/s: shock speed (reference, double)', \
     $w11 u 1:2 w lp pt 7 ps 1.4 dt 1 lc rgb '#8c564b' t 'Hugoniot 1000 m/s: shock pressure (reference, double)', \
     $w12 u 1:2 w lp pt 7 ps 1.4 dt 1 lc rgb '#e377c2' t 'Hugoniot 1000 m/s: shock speed (reference, double)'
unset output
