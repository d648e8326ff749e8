set terminal pngcairo noenhanced size 640,480 font 'sans,10'
set output 'io-conversion.png'
set title "Conversion throughput (input MB/s, median)"
set xlabel ''
set ylabel 'input MB/s'
set grid ytics
set style fill solid 0.8 border -1
set boxwidth 0.7
set xtics rotate by -30
set rmargin 5
set yrange [0:*]
unset key
plot 'io-conversion.dat' using 1:3:xtic(2) with boxes lc rgb '#4477aa', '' using 1:3:(sprintf('%.3g', $3)) with labels offset 0,0.7 notitle
