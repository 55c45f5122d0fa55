# Drawn by impactsph ballistic-limit; run `gnuplot /tmp/bl2/ballistic_curve.gp` to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output '/tmp/bl2/ballistic_curve.png'
set title 'plate-8mm: ballistic limit 150.0 m/s (spacing 2 mm, 6 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [82:418]
set yrange [-15.56754316:389.188579]
set object 1 rect from 133.33, graph 0 to 166.67, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 150, graph 0 to 150, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 150.0 m/s' at 150, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 0.8433542602; p1 = 2.249557889; v1 = 150
a2 = 0.8165969351; p2 = 2.837366266; v2 = 158.9201852
a3 = 0.9090909091; v3 = 152.5
$perforated << EOD
166.67 65.12812492
200 129.2823584
300 223.33064
400 321.6147348
EOD
$stopped << EOD
100
133.33
EOD
$reference0 << EOD
152.5 0
EOD
$reference1 << EOD
152.5 0
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 0.843, p = 2.25, v_{bl} = 150.0 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 0.817, p = 2.84, v_{bl} = 158.9 m/s', \
     ri(x, a3, 2, v3) w l lw 1.5 dt 3 lc rgb '#2ca02c' t 'reference: p = 2, a = m_p/(m_p+m_{plug}) = 0.909, v_{bl} = 152.5 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated', \
     $reference0 u 1:2 w p pt 9 ps 2 lc rgb 'black' t 'experiment (reference.csv)' noenhanced, \
     $reference1 u 1:2 w p pt 4 ps 1.6 lw 2 lc rgb '#9467bd' t 'F-sim (reference.csv)' noenhanced
unset output
