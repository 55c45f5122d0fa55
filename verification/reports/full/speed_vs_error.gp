# Drawn by impactsph verify; to redraw, run gnuplot on this file from the folder verify ran in (the
# output path below is relative to it).
set terminal pngcairo size 1000,750 enhanced font 'Sans,11'
set output 'verification/reports/full/speed_vs_error.png'
set title 'Speed against error: reference and gpu port, 1 thread(s)' noenhanced
set xlabel '|relative error|'
set ylabel 'wall time [s]'
set grid
set key below left Left reverse noenhanced
set logscale xy
set format x '10^{%L}'
$w0 << EOD
0.2628905798 0.217263441
0.1681283022 3.41650481
0.1487873734 8.266951065
0.112195325 60.82208572
0.0992351896 161.5865012
EOD
$w1 << EOD
0.001093212209 0.217263441
0.0002514594729 3.41650481
0.0003311779091 8.266951065
0.0004696898252 60.82208572
0.0005180730056 161.5865012
EOD
$w2 << EOD
0.002292068164 0.217263441
0.003901386767 3.41650481
0.003231408536 8.266951065
0.0004763913165 60.82208572
0.0002747404613 161.5865012
EOD
$w3 << EOD
0.2628905798 0.231016448
0.1681283022 3.507497133
0.1487873734 8.605341074
0.112195325 62.06949084
EOD
$w4 << EOD
0.001093212209 0.231016448
0.0002514594729 3.507497133
0.0003311779091 8.605341074
0.0004696898252 62.06949084
EOD
$w5 << EOD
0.002292068164 0.231016448
0.003901386767 3.507497133
0.003231408536 8.605341074
0.0004763913165 62.06949084
EOD
$w6 << EOD
0.2628622778 0.21103496
0.1681107733 3.251149845
0.1487920947 7.796018128
0.1122236403 56.0369708
EOD
$w7 << EOD
0.001081758241 0.21103496
0.0002539528452 3.251149845
0.0003307300127 7.796018128
0.000466042421 56.0369708
EOD
$w8 << EOD
0.002298497903 0.21103496
0.003894535002 3.251149845
0.003234461223 7.796018128
0.0005793695153 56.0369708
EOD
$w9 << EOD
0.004781294538 0.379824758
0.004648306268 5.323218013
0.0004557603408 43.34913292
0.0003284538108 91.73010787
EOD
$w10 << EOD
0.03847876599 0.379824758
0.01765394576 5.323218013
0.01133066322 43.34913292
0.0006766609421 91.73010787
EOD
$w11 << EOD
0.008956842748 0.194348547
0.00492459203 3.057541763
0.0006685533442 45.33704644
0.0004488257522 102.8337734
EOD
$w12 << EOD
0.03833844143 0.194348547
0.01824278613 3.057541763
0.001530970018 45.33704644
0.003792886127 102.8337734
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
