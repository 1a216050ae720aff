set terminal pngcairo noenhanced size 1500,640 font 'sans,10'
set output 'chart_ablation.png'
set multiplot layout 1,3 title 'the default mode with one term switched off: the change against the whole mode, geometric mean over the cells (above 0: the term helps)'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set grid ytics
set xtics rotate by -40 scale 0 font 'sans,9'
set bmargin 15
set key outside bottom center horizontal
set ylabel 'without the term / with it - 1 (%)'
set title 'mean distance'
plot 'ablation.dat' using 2:xtic(1) title 'tuned', '' using 3 title 'held out', '' using 4 title 'held out anew', '' using 5 title 'held out for the next term'
set title 'point-to-plane error'
plot 'ablation.dat' using 6:xtic(1) title 'tuned', '' using 7 title 'held out', '' using 8 title 'held out anew', '' using 9 title 'held out for the next term'
set title 'Hausdorff distance'
plot 'ablation.dat' using 10:xtic(1) title 'tuned', '' using 11 title 'held out', '' using 12 title 'held out anew', '' using 13 title 'held out for the next term'
unset multiplot
