# Drawn by impactsph at the end of the run: `gnuplot picture_taylor_bar.gp` in this folder redraws picture_taylor_bar.png from picture_taylor_bar.dat.
if (!exists("output")) output = 'picture_taylor_bar.png'
set terminal pngcairo size 1100,1271 noenhanced font 'Sans,12'
set output output
set title 'taylor-bar at t = 80 µs, coloured by plastic strain [-]'."\n".'cut x = 0 mm (symmetry plane), mirrored about y = 0 mm; spacing 0.508 mm'
set xlabel 'y [mm]'
set ylabel 'z [mm]'
set size ratio -1
set rmargin 12
set xrange [-7.787027504:7.787027504]
set yrange [-2.635028339:18.15109344]
set cbrange [0:1.605739384]
set cblabel 'plastic strain [-]'
set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')
set key top left inside opaque box
set tics out
set arrow 1 from -7.082413207,-1.842337255 to -5.082413207,-1.842337255 heads size screen 0.006,90 lw 2.5 lc rgb 'black' front
set label 1 '2 mm' at -6.082413207,-1.313876532 center front
plot 'picture_taylor_bar.dat' index 0 using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title 'bar'
unset output
