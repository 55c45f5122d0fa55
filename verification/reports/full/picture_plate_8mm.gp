# Drawn by impactsph at the end of the run: `gnuplot picture_plate_8mm.gp` in this folder redraws picture_plate_8mm.png from picture_plate_8mm.dat.
if (!exists("output")) output = 'picture_plate_8mm.png'
set terminal pngcairo size 1100,887 noenhanced font 'Sans,12'
set output output
set title 'plate-8mm at t = 80.05 µs, coloured by plastic strain [-]'."\n".'cut x = 0 mm (symmetry plane), mirrored about y = 0 mm; spacing 1.333 mm'
set xlabel 'y [mm]'
set ylabel 'z [mm]'
set size ratio -1
set rmargin 12
set xrange [-64.84958651:64.84958651]
set yrange [-43.99182389:65.17870528]
set cbrange [0:0.4538282286]
set cblabel 'plastic strain [-]'
set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')
set key top left inside opaque box
set tics out
set arrow 1 from -60.04591343,-38.58769168 to -40.04591343,-38.58769168 heads size screen 0.006,90 lw 2.5 lc rgb 'black' front
set label 1 '20 mm' at -50.04591343,-34.98493687 center front
plot 'picture_plate_8mm.dat' index 0 using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title 'plate', \
     'picture_plate_8mm.dat' index 1 using 1:2:3:4:5 with boxxyerror fs solid 1.0 border lc rgb '#505050' lc palette title 'projectile (outlined)', \
     'picture_plate_8mm.dat' index 2 using 1:2:3:4 with boxxyerror fs solid 1.0 noborder lc rgb '#1565ff' title 'plate failed (D >= 0.99)'
unset output
