set terminal pngcairo noenhanced size 1080,480 font 'sans,10'
set output 'extract-bricks_cloud.png'
set title "Per-brick extraction, clw >= 1e-05: one thread, same bricks for every contender, median of 5 round(s) per brick"
set xlabel ''
set ylabel 'Mcells/s per core'
set grid ytics
set logscale y
set style fill solid 0.8 border -1
set boxwidth 0.7
set xtics rotate by -30
set rmargin 23
set yrange [*:*]
unset key
plot 'extract-bricks_cloud.dat' using 1:3:xtic(2) with boxes lc rgb '#4477aa', '' using 1:3:(sprintf('%.3g', $3)) with labels offset 0,0.7 notitle
