# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'ballistic_curve.png'
set title 'plate-8mm: ballistic limit 153.1 m/s (spacing 2 mm, 8 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [127:183]
set yrange [-4.972868155:124.3217039]
set object 1 rect from 152.22, graph 0 to 154.07, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 153.145, graph 0 to 153.145, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 153.1 m/s' at 153.145, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 1.220253181; p1 = 1.859354024; v1 = 153.145
a2 = 1.138283659; p2 = 1.979485352; v2 = 153.4959891
a3 = 0.9090909091; v3 = 152.5
$perforated << EOD
154.07 15.47019666
155.93 28.07658352
157.78 40.44056455
163.33 65.07550009
180 105.0316129
EOD
$stopped << EOD
130
146.67
152.22
EOD
$reference0 << EOD
152.5 0
EOD
$reference1 << EOD
152.5 0
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 1.220, p = 1.86, v_{bl} = 153.1 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 1.138, p = 1.98, v_{bl} = 153.5 m/s', \
     ri(x, a3, 2, v3) w l lw 1.5 dt 3 lc rgb '#2ca02c' t 'reference: p = 2, a = m_p/(m_p+m_{plug}) = 0.909, v_{bl} = 152.5 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated', \
     $reference0 u 1:2 w p pt 9 ps 2 lc rgb 'black' t 'experiment (reference.csv)' noenhanced, \
     $reference1 u 1:2 w p pt 4 ps 1.6 lw 2 lc rgb '#9467bd' t 'F-sim (reference.csv)' noenhanced
unset output
