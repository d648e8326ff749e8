set terminal pngcairo noenhanced size 800,480 font 'sans,10'
set output 'extract-error-vs-time.png'
set title "Error against run time, whole level"
set xlabel 'seconds, one thread'
set ylabel 'error'
set grid ytics
set logscale x
set logscale y
set key outside right top
plot 'extract-error-vs-time.dat' index 0 using 1:2 with linespoints lw 2 title 'levels_cloud: volume error %', \
     'extract-error-vs-time.dat' index 1 using 1:2 with linespoints lw 2 title 'levels_cloud: mean surface distance (cells)', \
     'extract-error-vs-time.dat' index 2 using 1:2 with linespoints lw 2 title 'levels_dense: volume error %', \
     'extract-error-vs-time.dat' index 3 using 1:2 with linespoints lw 2 title 'levels_dense: mean surface distance (cells)'
