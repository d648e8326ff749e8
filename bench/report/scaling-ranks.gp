set terminal pngcairo noenhanced size 640,480 font 'sans,10'
set output 'scaling-ranks.png'
set title "Cold cut complete"
set xlabel ''
set ylabel 'ms (median)'
set grid ytics
set style fill solid 0.8 border -1
set boxwidth 0.7
set xtics rotate by -30
set rmargin 20
set yrange [0:*]
unset key
plot 'scaling-ranks.dat' using 1:3:xtic(2) with boxes lc rgb '#4477aa', '' using 1:3:(sprintf('%.3g', $3)) with labels offset 0,0.7 notitle
