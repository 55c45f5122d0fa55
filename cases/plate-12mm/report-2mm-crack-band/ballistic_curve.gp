# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'ballistic_curve.png'
set title 'plate-12mm: ballistic limit 168.8 m/s (spacing 2 mm, 5 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [146.4:213.6]
set yrange [-4.161186724:104.0296681]
set object 1 rect from 165, graph 0 to 172.5, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 168.75, graph 0 to 168.75, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 168.8 m/s' at 168.75, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 1.112467367; p1 = 1.386502516; v1 = 168.75
a2 = 0.8378363275; p2 = 1.746137792; v2 = 171.1578092
$perforated << EOD
172.5 12.30459374
180 36.55597523
210 88.34652246
EOD
$stopped << EOD
150
165
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 1.112, p = 1.39, v_{bl} = 168.8 m/s (fixed)', \
     ri(x, a2, p2, v2) w l lw 1.5 dt 2 lc rgb '#ff7f0e' t 'Recht-Ipson fit, all free: a = 0.838, p = 1.75, v_{bl} = 171.2 m/s', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
