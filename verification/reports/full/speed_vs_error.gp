# Drawn by impactsph verify; run `gnuplot speed_vs_error.png` in the report folder to redraw.
set terminal pngcairo size 1000,650 enhanced font 'Sans,11'
set output 'verification/reports/full/speed_vs_error.png'
set title 'Speed against error: reference solver, double, 1 thread(s)' noenhanced
set xlabel '|relative error|'
set ylabel 'wall time [s]'
set grid
set key outside right top noenhanced
set logscale xy
set format x '10^{%L}'
$w0 << EOD
0.2628905798 0.288903282
0.1681283022 4.470351783
0.1487873734 11.24180077
0.112195325 52.10428851
0.0992351896 276.0760544
EOD
$w1 << EOD
0.001093212209 0.288903282
0.0002514594729 4.470351783
0.0003311779091 11.24180077
0.0004696898252 52.10428851
0.0005180730056 276.0760544
EOD
$w2 << EOD
0.002292068164 0.288903282
0.003901386767 4.470351783
0.003231408536 11.24180077
0.0004763913165 52.10428851
0.0002747404613 276.0760544
EOD
$w3 << EOD
0.004781294538 0.636836889
0.004648306268 8.851435597
0.0004557603408 148.0241019
0.0003284538108 334.5498638
EOD
$w4 << EOD
0.03847876599 0.636836889
0.01765394576 8.851435597
0.01133066322 148.0241019
0.0006766609421 334.5498638
EOD
$w5 << EOD
0.008956842748 0.371773259
0.00492459203 5.412002689
0.0006685533442 104.3163062
0.0004488257522 257.6383267
EOD
$w6 << EOD
0.03833844143 0.371773259
0.01824278613 5.412002689
0.001530970018 104.3163062
0.003792886127 257.6383267
EOD
plot $w0 u 1:2 w lp pt 5 ps 1.4 lc rgb '#1f77b4' t 'elastic wave: velocity profile L1 (reference, double)', \
     $w1 u 1:2 w lp pt 7 ps 1.4 lc rgb '#d62728' t 'elastic wave: wave speed (reference, double)', \
     $w2 u 1:2 w lp pt 9 ps 1.4 lc rgb '#2ca02c' t 'elastic wave: stress amplitude (reference, double)', \
     $w3 u 1:2 w lp pt 11 ps 1.4 lc rgb '#ff7f0e' t 'Hugoniot 500 m/s: shock pressure (reference, double)', \
     $w4 u 1:2 w lp pt 5 ps 1.4 lc rgb '#9467bd' t 'Hugoniot 500 m/s: shock speed (reference, double)', \
     $w5 u 1:2 w lp pt 7 ps 1.4 lc rgb '#8c564b' t 'Hugoniot 1000 m/s: shock pressure (reference, double)', \
     $w6 u 1:2 w lp pt 9 ps 1.4 lc rgb '#e377c2' t 'Hugoniot 1000 m/s: shock speed (reference, double)'
unset output
