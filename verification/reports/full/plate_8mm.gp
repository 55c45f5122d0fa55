# Drawn by impactsph verify; to redraw, run gnuplot on this file in its folder.
set terminal pngcairo size 1000,750 enhanced font 'Sans,11'
set output 'plate_8mm.png'
set title '8 mm Weldox 460 E plate at 298 m/s: residual velocity against spacing' noenhanced
set xlabel 'spacing h [mm]'
set ylabel 'residual velocity [m/s]'
set grid
set key below left Left reverse noenhanced
set xrange [0:*]
$o0 << EOD
4 218.3135151
2 230.9271315
1.6 232.5438993
1.3333333 232.4394652
EOD
plot $o0 u 1:2 w lp pt 7 ps 1.4 lc rgb '#1f77b4' t '8 mm plate at 298 m/s: residual velocity, simulated', \
     232.7248599 w l lw 2 dt 2 lc rgb '#1f77b4' t '8 mm plate at 298 m/s: residual velocity, experiment 232.7'
unset output
