# Drawn by impactsph ballistic-limit; run `gnuplot runs/plate-8mm-bl-1mm/ballistic_curve.gp` to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'runs/plate-8mm-bl-1mm/ballistic_curve.png'
set title 'plate-8mm: ballistic limit 115.1 m/s (spacing 1 mm, 6 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [94.558:196.142]
set yrange [-5.989874962:149.7468741]
set object 1 rect from 110.08, graph 0 to 120.15, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 115.115, graph 0 to 115.115, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 115.1 m/s' at 115.115, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 0.9367401841; p1 = 1.712184062; v1 = 115.115
a2 = 0.8018873421; p2 = 2.294618552; v2 = 119.0238184
a3 = 0.9090909091; v3 = 152.5
$perforated << EOD
120.15 18.03792323
130.23 50.18859289
160.47 94.90203249
190.7 127.6258214
EOD
$stopped << EOD
100
110.08
EOD
$reference0 << EOD
152.5 0
EOD
$reference1 << EOD
152.5 0
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 0.937, p = 1.71, v_{bl} = 115.1 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 0.802, p = 2.29, v_{bl} = 119.0 m/s', \
     ri(x, a3, 2, v3) w l lw 1.5 dt 3 lc rgb '#2ca02c' t 'reference: p = 2, a = m_p/(m_p+m_{plug}) = 0.909, v_{bl} = 152.5 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated', \
     $reference0 u 1:2 w p pt 9 ps 2 lc rgb 'black' t 'experiment (reference.csv)' noenhanced, \
     $reference1 u 1:2 w p pt 4 ps 1.6 lw 2 lc rgb '#9467bd' t 'F-sim (reference.csv)' noenhanced
unset output
