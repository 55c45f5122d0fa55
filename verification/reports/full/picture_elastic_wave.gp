# Drawn by impactsph at the end of the run: `gnuplot picture_elastic_wave.gp` in this folder redraws picture_elastic_wave.png from picture_elastic_wave.dat.
if (!exists("output")) output = 'picture_elastic_wave.png'
set terminal pngcairo size 1100,450 noenhanced font 'Sans,12'
set output output
set title 'elastic-wave-convergence at t = 10 µs, coloured by speed [m/s]'."\n".'cut y = 0 mm (symmetry plane); spacing 0.4 mm'
set xlabel 'x [mm]'
set ylabel 'z [mm]'
set size ratio -1
set rmargin 12
set xrange [-3.932457733:103.9974022]
set yrange [-13.99090777:7.997402221]
set cbrange [0:10.01393414]
set cblabel 'speed [m/s]'
set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')
set key below horizontal
set tics out
set arrow 1 from 0.06494448727,-9.493830274 to 20.06494449,-9.493830274 heads size screen 0.006,90 lw 2.5 lc rgb 'black' front
set label 1 '20 mm' at 10.06494449,-6.495778608 center front
plot 'picture_elastic_wave.dat' index 0 using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title 'bar', \
     'picture_elastic_wave.dat' index 1 using 1:2:3:4:5 with boxxyerror fs solid 1.0 border lc rgb '#505050' lc palette title 'flyer (outlined)'
unset output
