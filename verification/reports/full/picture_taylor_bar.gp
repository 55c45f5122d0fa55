# Drawn by impactsph at the end of the run: `gnuplot picture_taylor_bar.gp` in this folder redraws picture_taylor_bar.png from picture_taylor_bar.dat.
if (!exists("output")) output = 'picture_taylor_bar.png'
set terminal pngcairo size 1100,1374 noenhanced font 'Sans,12'
set output output
set title 'taylor-bar at t = 80 µs, coloured by plastic strain [-]'."\n".'cut x = 0 mm (symmetry plane), mirrored about y = 0 mm; spacing 0.508 mm'
set xlabel 'y [mm]'
set ylabel 'z [mm]'
set size ratio -1
set rmargin 12
set xrange [-7.438755423:7.438755423]
set yrange [-2.684912626:19.12926441]
set cbrange [0:1.339727955]
set cblabel 'plastic strain [-]'
set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')
set key top left inside opaque box
set tics out
set arrow 1 from -6.699291794,-1.853016045 to -4.699291794,-1.853016045 heads size screen 0.006,90 lw 2.5 lc rgb 'black' front
set label 1 '2 mm' at -5.699291794,-1.298418323 center front
plot 'picture_taylor_bar.dat' index 0 using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title 'bar'
unset output
