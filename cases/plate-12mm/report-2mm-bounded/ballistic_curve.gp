# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'ballistic_curve.png'
set title 'plate-12mm: ballistic limit 156.7 m/s (spacing 2 mm, 6 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [136.4:203.6]
set yrange [-3.574770216:89.36925539]
set object 1 rect from 153.33, graph 0 to 160, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 156.665, graph 0 to 156.665, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 156.7 m/s' at 156.665, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 0.867224027; p1 = 1.469501187; v1 = 156.665
a2 = 0.6902188102; p2 = 1.794315249; v2 = 158.4990657
$perforated << EOD
160 11.3136576
180 51.23839092
200 75.81228971
EOD
$stopped << EOD
140
146.67
153.33
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 0.867, p = 1.47, v_{bl} = 156.7 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 0.690, p = 1.79, v_{bl} = 158.5 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
