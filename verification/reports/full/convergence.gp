# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1000,750 enhanced font 'Sans,11'
set output 'convergence.png'
set title 'Convergence against the closed forms (|relative error| against spacing)' noenhanced
set xlabel 'spacing h [mm]'
set ylabel '|relative error|'
set grid
set key below left Left reverse noenhanced
set logscale xy
set format y '10^{%L}'
$s0 << EOD
2 0.2628905798
1 0.1681283022
0.8 0.1487873734
0.5 0.112195325
0.4 0.0992351896
EOD
$s1 << EOD
2 0.001093212209
1 0.0002514594729
0.8 0.0003311779091
0.5 0.0004696898252
0.4 0.0005180730056
EOD
$s2 << EOD
2 0.002292068164
1 0.003901386767
0.8 0.003231408536
0.5 0.0004763913165
0.4 0.0002747404613
EOD
$s3 << EOD
0.5 0.004781294538
0.25 0.004648306268
0.125 0.0004557603408
0.1 0.0003284538108
EOD
$s4 << EOD
0.5 0.03847876599
0.25 0.01765394576
0.125 0.01133066322
0.1 0.0006766609421
EOD
$s5 << EOD
0.5 0.008956842748
0.25 0.00492459203
0.125 0.0006685533442
0.1 0.0004488257522
EOD
$s6 << EOD
0.5 0.03833844143
0.25 0.01824278613
0.125 0.001530970018
0.1 0.003792886127
EOD
plot $s0 u 1:2 w p pt 5 ps 1.4 lc rgb '#1f77b4' t 'elastic wave: velocity profile L1: order 0.60', \
     exp(-1.766548038)*x**(0.6049656826) w l lw 1.5 dt 2 lc rgb '#1f77b4' notitle, \
     $s1 u 1:2 w p pt 7 ps 1.4 lc rgb '#d62728' t 'elastic wave: wave speed: order 0.36', \
     exp(-7.588539902)*x**(0.3561867569) w l lw 1.5 dt 2 lc rgb '#d62728' notitle, \
     $s2 u 1:2 w p pt 9 ps 1.4 lc rgb '#2ca02c' t 'elastic wave: stress amplitude: order 1.45', \
     exp(-6.310162867)*x**(1.454845993) w l lw 1.5 dt 2 lc rgb '#2ca02c' notitle, \
     $s3 u 1:2 w p pt 11 ps 1.4 lc rgb '#ff7f0e' t 'Hugoniot 500 m/s: shock pressure: order 1.84', \
     exp(-3.636929411)*x**(1.838782787) w l lw 1.5 dt 2 lc rgb '#ff7f0e' notitle, \
     $s4 u 1:2 w p pt 5 ps 1.4 lc rgb '#9467bd' t 'Hugoniot 500 m/s: shock speed: order 1.99', \
     exp(-1.553229302)*x**(1.990276828) w l lw 1.5 dt 2 lc rgb '#9467bd' notitle, \
     $s5 u 1:2 w p pt 7 ps 1.4 lc rgb '#8c564b' t 'Hugoniot 1000 m/s: shock pressure: order 1.96', \
     exp(-3.088887051)*x**(1.96434819) w l lw 1.5 dt 2 lc rgb '#8c564b' notitle, \
     $s6 u 1:2 w p pt 9 ps 1.4 lc rgb '#e377c2' t 'Hugoniot 1000 m/s: shock speed: order 1.83', \
     exp(-1.870854425)*x**(1.832145808) w l lw 1.5 dt 2 lc rgb '#e377c2' notitle
unset output
