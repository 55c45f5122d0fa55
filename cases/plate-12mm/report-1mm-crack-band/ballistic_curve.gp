# Drawn by impactsph ballistic-limit; run `gnuplot ballistic_curve.gp` in this folder to redraw.
set terminal pngcairo size 900,600 enhanced font 'Sans,11'
set output 'ballistic_curve.png'
set title 'plate-12mm: ballistic limit 205.0 m/s (spacing 1 mm, 3 runs)' noenhanced
set xlabel 'impact velocity v_i [m/s]'
set ylabel 'residual velocity v_r [m/s]'
set grid
set key top left Left reverse box opaque
set xzeroaxis lt -1
set samples 1000
set xrange [187.48:212.52]
set yrange [-2.453585011:61.33962527]
set object 1 rect from 200, graph 0 to 210, graph 1 fc rgb '#e4e4e4' fs solid 1.0 noborder behind
set arrow 1 from 205, graph 0 to 205, graph 1 nohead dt 2 lc rgb '#555555'
set label 1 'v_{bl} = 205.0 m/s' at 205, graph 0.12 offset -0.8,0 right textcolor rgb '#555555'
ri(x, a, p, v) = x > v ? a*(x**p - v**p)**(1.0/p) : 0
$perforated << EOD
210 55.7632957
EOD
$stopped << EOD
190
200
EOD
plot $perforated u 1:2 w p pt 7 ps 1.6 lc rgb '#1f77b4' t 'simulated, perforated', \
     $stopped u 1:(0) w p pt 6 ps 1.6 lw 2 lc rgb '#d62728' t 'simulated, not perforated'
unset output
