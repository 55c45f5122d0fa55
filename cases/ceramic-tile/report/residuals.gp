set terminal pngcairo size 1200,600 noenhanced
set output 'residuals.png'
set multiplot layout 1,2 title "Ceramic tile (X): residual velocity and mass against particle spacing"
set xlabel "particle spacing (mm)"
set grid
set key below maxrows 3
set ylabel "residual velocity (m/s)"
set xrange [0:1.8]
plot 682 w l dt 2 lc rgb "black" t "experiment 682 m/s", \
     682*0.95 w l dt 3 lc rgb "gray" t "+-5 %", 682*1.05 w l dt 3 lc rgb "gray" notitle, \
     'residuals.dat' index 0 u 1:2 w lp pt 7 t "PAM", \
     '' index 1 u 1:2 w lp pt 5 t "PCM", \
     '' index 2 u 1:2 w p pt 9 ps 1.5 t "PAM, fixed h", \
     '-' u 1:2 w lp pt 6 dt 4 t "X Table 3 PAM"
0.8 676
0.6 692
0.4 715
0.3 728
e
set ylabel "residual mass (g)"
plot 6.42 w l dt 2 lc rgb "black" t "experiment 6.42 g", \
     6.42*0.9 w l dt 3 lc rgb "gray" t "+-10 %", 6.42*1.1 w l dt 3 lc rgb "gray" notitle, \
     'residuals.dat' index 0 u 1:3 w lp pt 7 t "PAM", \
     '' index 1 u 1:3 w lp pt 5 t "PCM", \
     '' index 2 u 1:3 w p pt 9 ps 1.5 t "PAM, fixed h", \
     '' index 0 u 1:4 w lp pt 7 dt 2 t "PAM, fraction x 10.60 g", \
     '-' u 1:2 w lp pt 6 dt 4 t "X Table 3 PAM"
0.8 6.65
0.6 7.23
0.4 7.27
0.3 7.58
e
unset multiplot
