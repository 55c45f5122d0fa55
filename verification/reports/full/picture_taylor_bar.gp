# Drawn by impactsph at the end of the run: `gnuplot picture_taylor_bar.gp` in this folder redraws picture_taylor_bar.png from picture_taylor_bar.dat.
if (!exists("output")) output = 'picture_taylor_bar.png'
set terminal pngcairo size 1100,1275 noenhanced font 'Sans,12'
set output output
set title 'taylor-bar at t = 80 µs, coloured by plastic strain [-]'."\n".'cut x = 0 mm (symmetry plane), mirrored about y = 0 mm; spacing 0.508 mm'
set xlabel 'y [mm]'
set ylabel 'z [mm]'
set size ratio -1
set rmargin 12
set xrange [-7.760449108:7.760449108]
set yrange [-2.636432503:18.1480976]
set cbrange [0:1.497852992]
set cblabel 'plastic strain [-]'
set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')
set key top left inside opaque box
set tics out
set arrow 1 from -7.055888766,-1.843802118 to -5.055888766,-1.843802118 heads size screen 0.006,90 lw 2.5 lc rgb 'black' front
set label 1 '2 mm' at -6.055888766,-1.315381861 center front
plot 'picture_taylor_bar.dat' index 0 using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title 'bar'
unset output
