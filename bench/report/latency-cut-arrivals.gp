set terminal pngcairo noenhanced size 800,480 font 'sans,10'
set output 'latency-cut-arrivals.png'
set title "Cut arrivals after a change"
set xlabel 'ms after the request'
set ylabel '% of the cut'
set grid ytics
set logscale x
set key outside right top
plot 'latency-cut-arrivals.dat' index 0 using 1:2 with lines lw 2 title 'cold start, prefetch on', \
     'latency-cut-arrivals.dat' index 1 using 1:2 with lines lw 2 title 'cold start, prefetch off', \
     'latency-cut-arrivals.dat' index 2 using 1:2 with lines lw 2 title 'scene change, prefetch on', \
     'latency-cut-arrivals.dat' index 3 using 1:2 with lines lw 2 title 'scene change, prefetch off', \
     'latency-cut-arrivals.dat' index 4 using 1:2 with lines lw 2 title 'time change, prefetch on', \
     'latency-cut-arrivals.dat' index 5 using 1:2 with lines lw 2 title 'time change, prefetch off'
