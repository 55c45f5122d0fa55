# Drawn by impactsph ballistic-limit; run `gnuplot runs/plate-8mm-bl-1mm-v2/ballistic_curve.gp` to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'runs/plate-8mm-bl-1mm-v2/ballistic_curve.png'
set title 'plate-8mm: ballistic limit 123.3 m/s (spacing 1 mm, 6 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [96.4:163.6]
set yrange [-4.595070832:114.8767708]
set object 1 rect from 120, graph 0 to 126.67, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 123.335, graph 0 to 123.335, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 123.3 m/s' at 123.335, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 1.64953786; p1 = 1.265845251; v1 = 123.335
a2 = 1.192004758; p2 = 1.631725973; v2 = 125.9757633
a3 = 0.9090909091; v3 = 152.5
$perforated << EOD
126.67 8.518132195
133.33 34.71577093
140 55.25048975
160 95.11131779
EOD
$stopped << EOD
100
120
EOD
$reference0 << EOD
152.5 0
EOD
$reference1 << EOD
152.5 0
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 1.650, p = 1.27, v_{bl} = 123.3 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 1.192, p = 1.63, v_{bl} = 126.0 m/s', \
     ri(x, a3, 2, v3) w l lw 1.5 dt 3 lc rgb '#2ca02c' t 'reference: p = 2, a = m_p/(m_p+m_{plug}) = 0.909, v_{bl} = 152.5 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated', \
     $reference0 u 1:2 w p pt 9 ps 2 lc rgb 'black' t 'experiment (reference.csv)' noenhanced, \
     $reference1 u 1:2 w p pt 4 ps 1.6 lw 2 lc rgb '#9467bd' t 'F-sim (reference.csv)' noenhanced
unset output
