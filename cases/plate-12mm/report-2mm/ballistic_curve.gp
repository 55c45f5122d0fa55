# Drawn by impactsph ballistic-limit; run `gnuplot runs/bl12-2mm/ballistic_curve.gp` to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'runs/bl12-2mm/ballistic_curve.png'
set title 'plate-12mm: ballistic limit 168.0 m/s (spacing 2 mm, 10 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [140.79:312.71]
set yrange [-8.906139479:222.653487]
set object 1 rect from 167.06, graph 0 to 168.95, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 168.005, graph 0 to 168.005, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 168.0 m/s' at 168.005, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 0.6776145846; p1 = 2.727837755; v1 = 168.005
a2 = 0.7540073551; p2 = 2.021949987; v2 = 162.2970933
$perforated << EOD
168.95 38.08115376
170.85 37.40994111
172.74 44.78874045
178.43 58.59993985
184.11 67.67798645
201.17 90.69981227
252.33 143.9465957
303.5 195.6896064
EOD
$stopped << EOD
150
167.06
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 0.678, p = 2.73, v_{bl} = 168.0 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 0.754, p = 2.02, v_{bl} = 162.3 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
