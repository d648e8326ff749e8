# Work-precision diagrams of bench/results/advect.json (made from advect.dat); run: gnuplot advect.gp
set terminal pngcairo noenhanced size 1500,900 font 'sans,10'
set output 'advect.png'
set multiplot layout 2,3 title 'Advection: max error after 1 h (16 start points) against field evaluations; errors below 1e-6 m drawn at 1e-6 m'
set logscale xy
set grid
set key bottom left
set xlabel 'field evaluations (16 trajectories)'
set ylabel 'max error (m)'
set title 'solid-body rotation (1 turn/h, 1 h)'
plot 'advect.dat' index 0 using 1:3 with linespoints lw 2 pt 7 title 'euler', \
     'advect.dat' index 1 using 1:3 with linespoints lw 2 pt 7 title 'rk4', \
     'advect.dat' index 2 using 1:3 with linespoints lw 2 pt 7 title 'dopri5'
set title 'shear layer (10 m/s per km, w 0.5 m/s, 1 h)'
plot 'advect.dat' index 3 using 1:3 with linespoints lw 2 pt 7 title 'euler', \
     'advect.dat' index 4 using 1:3 with linespoints lw 2 pt 7 title 'rk4', \
     'advect.dat' index 5 using 1:3 with linespoints lw 2 pt 7 title 'dopri5'
set title 'stiff convergence (rates 1e-3 and 1 /s, ratio 1e+03, 1 h)'
plot 'advect.dat' index 6 using 1:3 with linespoints lw 2 pt 7 title 'euler', \
     'advect.dat' index 7 using 1:3 with linespoints lw 2 pt 7 title 'rk4', \
     'advect.dat' index 8 using 1:3 with linespoints lw 2 pt 7 title 'dopri5'
set title 'stiff convergence (rates 1e-3 and 10 /s, ratio 1e+04, 1 h)'
plot 'advect.dat' index 9 using 1:3 with linespoints lw 2 pt 7 title 'euler', \
     'advect.dat' index 10 using 1:3 with linespoints lw 2 pt 7 title 'rk4', \
     'advect.dat' index 11 using 1:3 with linespoints lw 2 pt 7 title 'dopri5'
set title 'drifting vortices on a 5 km grid (1 h, reference RK4 0.25 s)'
plot 'advect.dat' index 12 using 1:3 with linespoints lw 2 pt 7 title 'euler', \
     'advect.dat' index 13 using 1:3 with linespoints lw 2 pt 7 title 'rk4', \
     'advect.dat' index 14 using 1:3 with linespoints lw 2 pt 7 title 'dopri5'
unset multiplot
