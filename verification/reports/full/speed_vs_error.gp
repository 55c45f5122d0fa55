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
0.2628905798 0.216078877
0.1681283022 3.933550201
0.1487873734 9.487946597
0.112195325 44.17024495
0.0992351896 138.5443296
EOD
$w1 << EOD
0.001093212209 0.216078877
0.0002514594729 3.933550201
0.0003311779091 9.487946597
0.0004696898252 44.17024495
0.0005180730056 138.5443296
EOD
$w2 << EOD
0.002292068164 0.216078877
0.003901386767 3.933550201
0.003231408536 9.487946597
0.0004763913165 44.17024495
0.0002747404613 138.5443296
EOD
$w3 << EOD
0.2628905798 0.217641113
0.1681283022 3.919683988
0.1487873734 9.690949308
0.112195325 43.96503205
EOD
$w4 << EOD
0.001093212209 0.217641113
0.0002514594729 3.919683988
0.0003311779091 9.690949308
0.0004696898252 43.96503205
EOD
$w5 << EOD
0.002292068164 0.217641113
0.003901386767 3.919683988
0.003231408536 9.690949308
0.0004763913165 43.96503205
EOD
$w6 << EOD
0.2628650948 0.215775671
0.1681159115 3.703943452
0.1487890735 8.779239417
0.1122287139 39.94575076
EOD
$w7 << EOD
0.001081702604 0.215775671
0.0002517275312 3.703943452
0.0003307237205 8.779239417
0.0004661255273 39.94575076
EOD
$w8 << EOD
0.002298594937 0.215775671
0.003900661413 3.703943452
0.0032286287 8.779239417
0.0005969372684 39.94575076
EOD
$w9 << EOD
0.004781294538 0.165521667
0.004648306268 2.524205077
0.0004557603408 40.9966909
0.0003284538108 99.70683207
EOD
$w10 << EOD
0.03847876599 0.165521667
0.01765394576 2.524205077
0.01133066322 40.9966909
0.0006766609421 99.70683207
EOD
$w11 << EOD
0.008956842748 0.198288899
0.00492459203 3.057356343
0.0006685533442 45.82593317
0.0004488257522 113.7133413
EOD
$w12 << EOD
0.03833844143 0.198288899
0.01824278613 3.057356343
0.001530970018 45.82593317
0.003792886127 113.7133413
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
