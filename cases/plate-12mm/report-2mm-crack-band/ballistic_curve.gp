# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'ballistic_curve.png'
set title 'plate-12mm: ballistic limit 183.8 m/s (spacing 2 mm, 5 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [146.4:213.6]
set yrange [-3.207440836:80.18602091]
set object 1 rect from 180, graph 0 to 187.5, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 183.75, graph 0 to 183.75, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 183.8 m/s' at 183.75, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
a1 = 0.4036438517; p1 = 4.358784355; v1 = 183.75
$perforated << EOD
187.5 44.78986856
195 52.70200875
210 71.80662284
EOD
$stopped << EOD
150
180
EOD
plot ri(x, a1, p1, v1) w l lw 2 lc rgb '#1f77b4' t 'Recht-Ipson fit: a = 0.404, p = 4.36, v_{bl} = 183.8 m/s (fixed)', \
     $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
