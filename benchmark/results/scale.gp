set terminal pngcairo size 900,540
set output 'scale.png'
set logscale x
set key outside right
set xlabel 'input points'
set ylabel 'microseconds per input point'
set yrange [0:*]
set grid
set title 'lion samples to 10%, 2 hardware threads'
plot 'scale.dat' using 1:3 with linespoints title 'default, 2 threads', \
     '' using 1:4 with linespoints title 'default, 1 thread', \
     '' using 1:5 with linespoints title 'paper, 2 threads', \
     '' using 1:6 with linespoints title 'program, 2 threads', \
     '' using 1:2 with linespoints dashtype 2 title 'read + pca pass'
