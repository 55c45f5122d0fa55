set terminal pngcairo size 900,600
set output 'speed.png'
set logscale xy
set xlabel 'neighbours within the kernel support'
set ylabel 'particle-steps/s, one core'
set title 'Whole steps of the 8000-particle block, one thread (commit 401d8bb)'
set grid
set key top right
plot 'speed.dat' index 0 with linespoints lw 2 title 'reference (double)', \
     'speed.dat' index 1 with linespoints lw 2 title 'gpu port host build (float)', \
     'speed.dat' index 2 with linespoints lw 2 title 'gpu port host build (double)', \
     'speed.dat' index 3 with linespoints dt 2 lw 2 title 'reference (double), earlier commit'
