set terminal pngcairo size 800,560
set output "limit_vs_spacing.png"
set xlabel "particle spacing [mm]"
set ylabel "ballistic limit [m/s]"
set title "8 mm Weldox 460 E plate, 197 g blunt projectile"
set xrange [0:2.2]
set yrange [120:180]
set key bottom left
set grid
plot 152.5*0.97 with filledcurves y1=152.5*1.03 fc rgb "#dddddd" title "experiment +-3 %", 152.5 with lines dt 2 lc rgb "black" title "experiment 152.5 m/s", "limit_vs_spacing.dat" index 0 using 1:2:3:4 with yerrorlines pt 7 lc 1 title "fracture-energy", "limit_vs_spacing.dat" index 2 using 1:2 with points pt 6 ps 1.5 lc 1 title "fracture-energy, Recht-Ipson p = 2 estimate", "limit_vs_spacing.dat" index 4 using 1:2 with points pt 11 ps 2 lc 1 title "fracture-energy, every run perforated: limit below", "limit_vs_spacing.dat" index 1 using 1:2:3:4 with yerrorlines pt 7 lc 2 title "nonlocal", "limit_vs_spacing.dat" index 3 using 1:2 with points pt 6 ps 1.5 lc 2 title "nonlocal, Recht-Ipson p = 2 estimate"
