set terminal pngcairo size 900,600
set output "residual_curve.png"
set xlabel "impact speed (m/s)"
set ylabel "residual speed (m/s)"
set key top left
set grid
set xrange [100:312.9]
set samples 500
ri(a,p,vb,x) = x > vb ? a*(x**p - vb**p)**(1.0/p) : 0
plot ri(0.909091,2,152.5,x) lw 2 lc rgb "black" title "experiments: Recht-Ipson, p = 2, v_{bl} = 152.5 m/s", ri(0.951945,1.94099,152.5,x) dt 2 lw 2 lc rgb "blue" title "fit: a = 0.952, p = 1.94, v_{bl} = 152.5 m/s", ri(0.89397,2.27582,154.774,x) dt 3 lw 2 lc rgb "dark-green" title "fit, all free: a = 0.894, p = 2.28, v_{bl} = 154.8 m/s", "residual_curve.dat" using 1:($3 > 0 ? $2 : 1/0) with points pt 7 ps 1.5 lc rgb "red" title "simulated, 1 mm, perforated", "residual_curve.dat" using 1:($3 > 0 ? 1/0 : $2) with points pt 6 ps 1.5 lc rgb "red" title "simulated, held (rebound)"
