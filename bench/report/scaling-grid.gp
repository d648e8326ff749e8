set terminal pngcairo noenhanced size 800,480 font 'sans,10'
set output 'scaling-grid.png'
set title "Cost against grid size"
set xlabel 'million cells'
set ylabel 'seconds (median)'
set grid ytics
set logscale x
set logscale y
set key outside right top
plot 'scaling-grid.dat' index 0 using 1:2 with linespoints lw 2 title 'conversion', \
     'scaling-grid.dat' index 1 using 1:2 with linespoints lw 2 title 'whole level 0', \
     'scaling-grid.dat' index 2 using 1:2 with linespoints lw 2 title 'overview cut'
