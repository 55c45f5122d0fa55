# Drawn by impactsph ballistic-limit; run `gnuplot runs/bl12-2mm-v2/ballistic_curve.gp` to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'runs/bl12-2mm-v2/ballistic_curve.png'
set title 'plate-12mm: ballistic limit 176.4 m/s (spacing 2 mm, 7 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [140.79:312.71]
set yrange [-9.347202654:233.6800663]
set object 1 rect from 173.99, graph 0 to 178.79, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 176.39, graph 0 to 176.39, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 176.4 m/s' at 176.39, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 0.8226117675; p1 = 2.000556889; v1 = 176.39
a2 = 0.7821731495; p2 = 2.227533941; v2 = 177.9004733
$perforated << EOD
178.79 18.36779232
188.38 57.70461545
226.75 118.7261962
303.5 202.1283607
EOD
$stopped << EOD
150
169.19
173.99
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 0.823, p = 2.00, v_{bl} = 176.4 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 0.782, p = 2.23, v_{bl} = 177.9 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
