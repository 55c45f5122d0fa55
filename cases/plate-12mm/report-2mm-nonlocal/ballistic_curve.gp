# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'ballistic_curve.png'
set title 'plate-12mm: ballistic limit 190.0 m/s (spacing 2 mm, 6 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [136.4:203.6]
set yrange [-1.93492673:48.37316826]
set object 1 rect from 186.67, graph 0 to 193.33, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 190, graph 0 to 190, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 190.0 m/s' at 190, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 1.513916823; p1 = 1.271225507; v1 = 190
$perforated << EOD
193.33 14.45644708
200 34.46030437
EOD
$stopped << EOD
140
160
180
186.67
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 1.514, p = 1.27, v_{bl} = 190.0 m/s (fixed)', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
