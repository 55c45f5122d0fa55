# Drawn by impactsph at the end of the run: `gnuplot picture_hugoniot.gp` in this folder redraws picture_hugoniot.png from picture_hugoniot.dat.
if (!exists("output")) output = 'picture_hugoniot.png'
set terminal pngcairo size 1100,450 noenhanced font 'Sans,12'
set output output
set title 'hugoniot-4340 at t = 1.2 µs, coloured by pressure [GPa]'."\n".'cut y = 0 mm (symmetry plane); spacing 0.1 mm'
set xlabel 'x [mm]'
set ylabel 'z [mm]'
set size ratio -1
set rmargin 12
set xrange [-10.152:10.152]
set yrange [-2.632:2.252]
set cbrange [8.562845777e-11:21.0075565]
set cblabel 'pressure [GPa]'
set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')
set key below horizontal
set tics out
set arrow 1 from -9.4,-1.786 to -7.4,-1.786 heads size screen 0.006,90 lw 2.5 lc rgb 'black' front
set label 1 '2 mm' at -8.4,-1.222 center front
plot 'picture_hugoniot.dat' index 0 using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title 'target', \
     'picture_hugoniot.dat' index 1 using 1:2:3:4:5 with boxxyerror fs solid 1.0 border lc rgb '#505050' lc palette title 'flyer (outlined)'
unset output
