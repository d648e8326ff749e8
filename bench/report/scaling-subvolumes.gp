set terminal pngcairo noenhanced size 800,480 font 'sans,10'
set output 'scaling-subvolumes.png'
set title "Cost against sub-volumes"
set xlabel 'sub-volumes'
set ylabel 'seconds (median)'
set grid ytics
set key outside right top
plot 'scaling-subvolumes.dat' index 0 using 1:2 with linespoints lw 2 title 'whole level 0'
