# Drawn by impactsph at the end of the run: `gnuplot picture_ceramic_tile.gp` in this folder redraws picture_ceramic_tile.png from picture_ceramic_tile.dat.
if (!exists("output")) output = 'picture_ceramic_tile.png'
set terminal pngcairo size 1100,771 noenhanced font 'Sans,12'
set output output
set title 'ceramic-tile at t = 60 µs, coloured by damage D [-]'."\n".'cut x = 0 mm (symmetry plane), mirrored about y = 0 mm; spacing 1.27 mm'
set xlabel 'y [mm]'
set ylabel 'z [mm]'
set size ratio -1
set rmargin 12
set xrange [-55.88049059:55.88049059]
set yrange [-60.9993453:16.52885548]
set cbrange [0:1]
set cblabel 'damage D [-]'
set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')
set key top left inside opaque box
set tics out
set arrow 1 from -51.74119499,-56.34263775 to -31.74119499,-56.34263775 heads size screen 0.006,90 lw 2.5 lc rgb 'black' front
set label 1 '20 mm' at -41.74119499,-53.23816605 center front
plot 'picture_ceramic_tile.dat' index 0 using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title 'tile', \
     'picture_ceramic_tile.dat' index 1 using 1:2:3:4:5 with boxxyerror fs solid 1.0 border lc rgb '#505050' lc palette title 'rod (outlined)', \
     'picture_ceramic_tile.dat' index 2 using 1:2:3:4 with boxxyerror fs solid 1.0 noborder lc rgb '#1565ff' title 'tile failed (D >= 0.99)', \
     'picture_ceramic_tile.dat' index 3 using 1:2:3:4 with boxxyerror fs solid 1.0 border lc rgb '#505050' lc rgb '#2e9d3a' title 'rod failed (D >= 0.99)'
unset output
