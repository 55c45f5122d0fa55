# Drawn by impactsph verify; run `gnuplot speed_vs_error.png` in the report folder to redraw.
set terminal pngcairo size 1000,750 enhanced font 'Sans,11'
set output 'verification/reports/fast/speed_vs_error.png'
set title 'Speed against error: reference solver, double, 1 thread(s)' noenhanced
set xlabel '|relative error|'
set ylabel 'wall time [s]'
set grid
set key below left Left reverse noenhanced
set logscale xy
set format x '10^{%L}'
$w0 << EOD
0.2628905798 0.601734812
0.1681283022 9.400813849
0.1487873734 31.93319562
0.112195325 219.2288608
EOD
$w1 << EOD
0.001093212209 0.601734812
0.0002514594729 9.400813849
0.0003311779091 31.93319562
0.0004696898252 219.2288608
EOD
$w2 << EOD
0.002292068164 0.601734812
0.003901386767 9.400813849
0.003231408536 31.93319562
0.0004763913165 219.2288608
EOD
$w3 << EOD
0.004781294538 0.662763872
0.004648306268 11.45893395
0.0004557603408 141.1070327
0.0003284538108 261.7375773
EOD
$w4 << EOD
0.03847876599 0.662763872
0.01765394576 11.45893395
0.01133066322 141.1070327
0.0006766609421 261.7375773
EOD
$w5 << EOD
0.008956842748 0.423705943
0.00492459203 6.657600841
0.0006685533442 103.1861244
0.0004488257522 265.1359195
EOD
$w6 << EOD
0.03833844143 0.423705943
0.01824278613 6.657600841
0.001530970018 103.1861244
0.003792886127 265.1359195
EOD
plot $w0 u 1:2 w lp pt 5 ps 1.4 lc rgb '#1f77b4' t 'elastic wave: velocity profile L1 (reference, double)', \
     $w1 u 1:2 w lp pt 7 ps 1.4 lc rgb '#d62728' t 'elastic wave: wave speed (reference, double)', \
     $w2 u 1:2 w lp pt 9 ps 1.4 lc rgb '#2ca02c' t 'elastic wave: stress amplitude (reference, double)', \
     $w3 u 1:2 w lp pt 11 ps 1.4 lc rgb '#ff7f0e' t 'Hugoniot 500 m/s: shock pressure (reference, double)', \
     $w4 u 1:2 w lp pt 5 ps 1.4 lc rgb '#9467bd' t 'Hugoniot 500 m/s: shock speed (reference, double)', \
     $w5 u 1:2 w lp pt 7 ps 1.4 lc rgb '#8c564b' t 'Hugoniot 1000 m/s: shock pressure (reference, double)', \
     $w6 u 1:2 w lp pt 9 ps 1.4 lc rgb '#e377c2' t 'Hugoniot 1000 m/s: shock speed (reference, double)'
unset output
