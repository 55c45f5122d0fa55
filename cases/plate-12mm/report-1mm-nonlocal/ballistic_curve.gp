# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'ballistic_curve.png'
set title 'plate-12mm: ballistic limit 182.0 m/s (spacing 1 mm, 3 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [170.78:187.22]
set yrange [-1.110902657:27.77256642]
set object 1 rect from 179, graph 0 to 185, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 182, graph 0 to 182, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 182.0 m/s' at 182, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
$perforated << EOD
185 25.24778766
EOD
$stopped << EOD
173
179
EOD
plot $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
