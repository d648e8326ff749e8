set terminal pngcairo noenhanced size 1440,480 font 'sans,10'
set output 'scene-economy.png'
set title "Bytes read, % of the whole time step"
set xlabel ''
set ylabel '% of the step'
set grid ytics
set logscale y
set style fill solid 0.8 border -1
set boxwidth 0.7
set xtics rotate by -30
set rmargin 22
set yrange [*:*]
unset key
plot 'scene-economy.dat' using 1:3:xtic(2) with boxes lc rgb '#4477aa', '' using 1:3:(sprintf('%.3g', $3)) with labels offset 0,0.7 notitle
