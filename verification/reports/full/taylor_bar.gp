# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1000,750 enhanced font 'Sans,11'
set output 'taylor_bar.png'
set title 'Taylor bar (OFHC copper, 190 m/s): final shape against spacing' noenhanced
set xlabel 'spacing h [mm]'
set ylabel '[mm]'
set grid
set key below left Left reverse noenhanced
set xrange [0:*]
$o0 << EOD
1.27 18.13998677
0.8467 17.75274716
0.635 17.53907555
0.508 17.44647914
EOD
$o1 << EOD
1.27 11.54150818
0.8467 12.27894746
0.635 13.39045902
0.508 13.72941552
EOD
plot $o0 u 1:2 w lp pt 7 ps 1.4 lc rgb '#1f77b4' t 'Taylor bar: final length, simulated', \
     16.21 w l lw 2 dt 2 lc rgb '#1f77b4' t 'Taylor bar: final length, experiment 16.21', \
     $o1 u 1:2 w lp pt 7 ps 1.4 lc rgb '#d62728' t 'Taylor bar: impact-face diameter, simulated', \
     13.56 w l lw 2 dt 2 lc rgb '#d62728' t 'Taylor bar: impact-face diameter, experiment 13.56'
unset output
