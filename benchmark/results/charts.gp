set terminal pngcairo noenhanced size 1800,1100 font 'sans,10'
set logscale x
set xlabel 'points kept (%)'
set grid
unset key
set output 'chart_mean_distance.png'
set multiplot layout 2,3 title 'mean distance from the input to the result / diagonal'
set logscale y
set title 'replica_2mm'
plot 'data_replica_2mm.dat' index 0 using 1:2 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_2mm.dat' index 1 using 1:2 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_2mm.dat' index 2 using 1:2 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_2mm.dat' index 3 using 1:2 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_2mm.dat' index 4 using 1:2 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_2mm.dat' index 5 using 1:2 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_2mm.dat' index 6 using 1:2 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_2mm.dat' index 7 using 1:2 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_2mm.dat' index 8 using 1:2 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_2mm.dat' index 9 using 1:2 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'replica_1.2mm'
plot 'data_replica_1.2mm.dat' index 0 using 1:2 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_1.2mm.dat' index 1 using 1:2 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_1.2mm.dat' index 2 using 1:2 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_1.2mm.dat' index 3 using 1:2 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_1.2mm.dat' index 4 using 1:2 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_1.2mm.dat' index 5 using 1:2 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_1.2mm.dat' index 6 using 1:2 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_1.2mm.dat' index 7 using 1:2 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_1.2mm.dat' index 8 using 1:2 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_1.2mm.dat' index 9 using 1:2 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'lion'
plot 'data_lion.dat' index 0 using 1:2 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_lion.dat' index 1 using 1:2 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_lion.dat' index 2 using 1:2 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_lion.dat' index 3 using 1:2 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_lion.dat' index 4 using 1:2 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_lion.dat' index 5 using 1:2 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_lion.dat' index 6 using 1:2 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_lion.dat' index 7 using 1:2 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_lion.dat' index 8 using 1:2 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_lion.dat' index 9 using 1:2 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'fandisk'
plot 'data_fandisk.dat' index 0 using 1:2 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_fandisk.dat' index 1 using 1:2 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_fandisk.dat' index 2 using 1:2 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_fandisk.dat' index 3 using 1:2 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_fandisk.dat' index 4 using 1:2 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_fandisk.dat' index 5 using 1:2 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_fandisk.dat' index 6 using 1:2 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_fandisk.dat' index 7 using 1:2 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_fandisk.dat' index 8 using 1:2 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_fandisk.dat' index 9 using 1:2 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'b9_training'
plot 'data_b9_training.dat' index 0 using 1:2 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_b9_training.dat' index 1 using 1:2 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_b9_training.dat' index 2 using 1:2 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_b9_training.dat' index 3 using 1:2 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_b9_training.dat' index 4 using 1:2 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_b9_training.dat' index 5 using 1:2 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_b9_training.dat' index 6 using 1:2 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_b9_training.dat' index 7 using 1:2 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_b9_training.dat' index 8 using 1:2 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_b9_training.dat' index 9 using 1:2 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set key center center box font 'sans,11'
unset title
unset border
unset tics
unset grid
unset xlabel
set xrange [0:1]
set yrange [0:1]
unset logscale
plot NaN with linespoints lw 3 pt 1 lc rgb '#d62728' title 'entropy, lowest first', NaN with linespoints lw 3 pt 2 lc rgb '#ff7f0e' title 'entropy, highest first', NaN with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' title 'equidistant E1 (every i-th)', NaN with linespoints lw 1.5 pt 4 lc rgb '#17becf' title 'equidistant E2 (spacing)', NaN with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' title 'bounding sphere', NaN with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' title 'curvature', NaN with linespoints lw 1.5 pt 7 lc rgb '#000000' title 'CGAL grid', NaN with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' title 'CGAL hierarchy', NaN with linespoints lw 1.5 pt 9 lc rgb '#9467bd' title 'CGAL WLOP', NaN with linespoints lw 1.5 pt 10 lc rgb '#e377c2' title 'CGAL random'
unset key
set border
set tics
set grid
set xlabel 'points kept (%)'
set autoscale
set logscale x
unset multiplot
set output 'chart_p99_distance.png'
set multiplot layout 2,3 title '99th percentile of that distance / diagonal'
set logscale y
set title 'replica_2mm'
plot 'data_replica_2mm.dat' index 0 using 1:3 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_2mm.dat' index 1 using 1:3 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_2mm.dat' index 2 using 1:3 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_2mm.dat' index 3 using 1:3 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_2mm.dat' index 4 using 1:3 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_2mm.dat' index 5 using 1:3 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_2mm.dat' index 6 using 1:3 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_2mm.dat' index 7 using 1:3 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_2mm.dat' index 8 using 1:3 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_2mm.dat' index 9 using 1:3 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'replica_1.2mm'
plot 'data_replica_1.2mm.dat' index 0 using 1:3 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_1.2mm.dat' index 1 using 1:3 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_1.2mm.dat' index 2 using 1:3 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_1.2mm.dat' index 3 using 1:3 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_1.2mm.dat' index 4 using 1:3 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_1.2mm.dat' index 5 using 1:3 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_1.2mm.dat' index 6 using 1:3 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_1.2mm.dat' index 7 using 1:3 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_1.2mm.dat' index 8 using 1:3 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_1.2mm.dat' index 9 using 1:3 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'lion'
plot 'data_lion.dat' index 0 using 1:3 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_lion.dat' index 1 using 1:3 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_lion.dat' index 2 using 1:3 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_lion.dat' index 3 using 1:3 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_lion.dat' index 4 using 1:3 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_lion.dat' index 5 using 1:3 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_lion.dat' index 6 using 1:3 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_lion.dat' index 7 using 1:3 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_lion.dat' index 8 using 1:3 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_lion.dat' index 9 using 1:3 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'fandisk'
plot 'data_fandisk.dat' index 0 using 1:3 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_fandisk.dat' index 1 using 1:3 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_fandisk.dat' index 2 using 1:3 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_fandisk.dat' index 3 using 1:3 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_fandisk.dat' index 4 using 1:3 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_fandisk.dat' index 5 using 1:3 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_fandisk.dat' index 6 using 1:3 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_fandisk.dat' index 7 using 1:3 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_fandisk.dat' index 8 using 1:3 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_fandisk.dat' index 9 using 1:3 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'b9_training'
plot 'data_b9_training.dat' index 0 using 1:3 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_b9_training.dat' index 1 using 1:3 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_b9_training.dat' index 2 using 1:3 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_b9_training.dat' index 3 using 1:3 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_b9_training.dat' index 4 using 1:3 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_b9_training.dat' index 5 using 1:3 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_b9_training.dat' index 6 using 1:3 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_b9_training.dat' index 7 using 1:3 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_b9_training.dat' index 8 using 1:3 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_b9_training.dat' index 9 using 1:3 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set key center center box font 'sans,11'
unset title
unset border
unset tics
unset grid
unset xlabel
set xrange [0:1]
set yrange [0:1]
unset logscale
plot NaN with linespoints lw 3 pt 1 lc rgb '#d62728' title 'entropy, lowest first', NaN with linespoints lw 3 pt 2 lc rgb '#ff7f0e' title 'entropy, highest first', NaN with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' title 'equidistant E1 (every i-th)', NaN with linespoints lw 1.5 pt 4 lc rgb '#17becf' title 'equidistant E2 (spacing)', NaN with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' title 'bounding sphere', NaN with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' title 'curvature', NaN with linespoints lw 1.5 pt 7 lc rgb '#000000' title 'CGAL grid', NaN with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' title 'CGAL hierarchy', NaN with linespoints lw 1.5 pt 9 lc rgb '#9467bd' title 'CGAL WLOP', NaN with linespoints lw 1.5 pt 10 lc rgb '#e377c2' title 'CGAL random'
unset key
set border
set tics
set grid
set xlabel 'points kept (%)'
set autoscale
set logscale x
unset multiplot
set output 'chart_hausdorff.png'
set multiplot layout 2,3 title 'maximum of that distance (one-sided Hausdorff) / diagonal'
set logscale y
set title 'replica_2mm'
plot 'data_replica_2mm.dat' index 0 using 1:4 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_2mm.dat' index 1 using 1:4 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_2mm.dat' index 2 using 1:4 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_2mm.dat' index 3 using 1:4 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_2mm.dat' index 4 using 1:4 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_2mm.dat' index 5 using 1:4 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_2mm.dat' index 6 using 1:4 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_2mm.dat' index 7 using 1:4 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_2mm.dat' index 8 using 1:4 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_2mm.dat' index 9 using 1:4 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'replica_1.2mm'
plot 'data_replica_1.2mm.dat' index 0 using 1:4 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_1.2mm.dat' index 1 using 1:4 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_1.2mm.dat' index 2 using 1:4 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_1.2mm.dat' index 3 using 1:4 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_1.2mm.dat' index 4 using 1:4 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_1.2mm.dat' index 5 using 1:4 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_1.2mm.dat' index 6 using 1:4 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_1.2mm.dat' index 7 using 1:4 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_1.2mm.dat' index 8 using 1:4 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_1.2mm.dat' index 9 using 1:4 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'lion'
plot 'data_lion.dat' index 0 using 1:4 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_lion.dat' index 1 using 1:4 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_lion.dat' index 2 using 1:4 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_lion.dat' index 3 using 1:4 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_lion.dat' index 4 using 1:4 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_lion.dat' index 5 using 1:4 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_lion.dat' index 6 using 1:4 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_lion.dat' index 7 using 1:4 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_lion.dat' index 8 using 1:4 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_lion.dat' index 9 using 1:4 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'fandisk'
plot 'data_fandisk.dat' index 0 using 1:4 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_fandisk.dat' index 1 using 1:4 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_fandisk.dat' index 2 using 1:4 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_fandisk.dat' index 3 using 1:4 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_fandisk.dat' index 4 using 1:4 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_fandisk.dat' index 5 using 1:4 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_fandisk.dat' index 6 using 1:4 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_fandisk.dat' index 7 using 1:4 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_fandisk.dat' index 8 using 1:4 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_fandisk.dat' index 9 using 1:4 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'b9_training'
plot 'data_b9_training.dat' index 0 using 1:4 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_b9_training.dat' index 1 using 1:4 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_b9_training.dat' index 2 using 1:4 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_b9_training.dat' index 3 using 1:4 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_b9_training.dat' index 4 using 1:4 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_b9_training.dat' index 5 using 1:4 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_b9_training.dat' index 6 using 1:4 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_b9_training.dat' index 7 using 1:4 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_b9_training.dat' index 8 using 1:4 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_b9_training.dat' index 9 using 1:4 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set key center center box font 'sans,11'
unset title
unset border
unset tics
unset grid
unset xlabel
set xrange [0:1]
set yrange [0:1]
unset logscale
plot NaN with linespoints lw 3 pt 1 lc rgb '#d62728' title 'entropy, lowest first', NaN with linespoints lw 3 pt 2 lc rgb '#ff7f0e' title 'entropy, highest first', NaN with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' title 'equidistant E1 (every i-th)', NaN with linespoints lw 1.5 pt 4 lc rgb '#17becf' title 'equidistant E2 (spacing)', NaN with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' title 'bounding sphere', NaN with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' title 'curvature', NaN with linespoints lw 1.5 pt 7 lc rgb '#000000' title 'CGAL grid', NaN with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' title 'CGAL hierarchy', NaN with linespoints lw 1.5 pt 9 lc rgb '#9467bd' title 'CGAL WLOP', NaN with linespoints lw 1.5 pt 10 lc rgb '#e377c2' title 'CGAL random'
unset key
set border
set tics
set grid
set xlabel 'points kept (%)'
set autoscale
set logscale x
unset multiplot
set output 'chart_point_to_plane.png'
set multiplot layout 2,3 title 'point-to-plane RMS error of the input / diagonal'
set logscale y
set title 'replica_2mm'
plot 'data_replica_2mm.dat' index 0 using 1:5 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_2mm.dat' index 1 using 1:5 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_2mm.dat' index 2 using 1:5 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_2mm.dat' index 3 using 1:5 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_2mm.dat' index 4 using 1:5 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_2mm.dat' index 5 using 1:5 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_2mm.dat' index 6 using 1:5 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_2mm.dat' index 7 using 1:5 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_2mm.dat' index 8 using 1:5 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_2mm.dat' index 9 using 1:5 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'replica_1.2mm'
plot 'data_replica_1.2mm.dat' index 0 using 1:5 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_1.2mm.dat' index 1 using 1:5 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_1.2mm.dat' index 2 using 1:5 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_1.2mm.dat' index 3 using 1:5 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_1.2mm.dat' index 4 using 1:5 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_1.2mm.dat' index 5 using 1:5 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_1.2mm.dat' index 6 using 1:5 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_1.2mm.dat' index 7 using 1:5 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_1.2mm.dat' index 8 using 1:5 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_1.2mm.dat' index 9 using 1:5 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'lion'
plot 'data_lion.dat' index 0 using 1:5 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_lion.dat' index 1 using 1:5 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_lion.dat' index 2 using 1:5 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_lion.dat' index 3 using 1:5 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_lion.dat' index 4 using 1:5 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_lion.dat' index 5 using 1:5 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_lion.dat' index 6 using 1:5 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_lion.dat' index 7 using 1:5 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_lion.dat' index 8 using 1:5 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_lion.dat' index 9 using 1:5 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'fandisk'
plot 'data_fandisk.dat' index 0 using 1:5 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_fandisk.dat' index 1 using 1:5 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_fandisk.dat' index 2 using 1:5 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_fandisk.dat' index 3 using 1:5 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_fandisk.dat' index 4 using 1:5 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_fandisk.dat' index 5 using 1:5 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_fandisk.dat' index 6 using 1:5 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_fandisk.dat' index 7 using 1:5 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_fandisk.dat' index 8 using 1:5 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_fandisk.dat' index 9 using 1:5 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'b9_training'
plot 'data_b9_training.dat' index 0 using 1:5 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_b9_training.dat' index 1 using 1:5 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_b9_training.dat' index 2 using 1:5 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_b9_training.dat' index 3 using 1:5 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_b9_training.dat' index 4 using 1:5 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_b9_training.dat' index 5 using 1:5 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_b9_training.dat' index 6 using 1:5 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_b9_training.dat' index 7 using 1:5 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_b9_training.dat' index 8 using 1:5 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_b9_training.dat' index 9 using 1:5 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set key center center box font 'sans,11'
unset title
unset border
unset tics
unset grid
unset xlabel
set xrange [0:1]
set yrange [0:1]
unset logscale
plot NaN with linespoints lw 3 pt 1 lc rgb '#d62728' title 'entropy, lowest first', NaN with linespoints lw 3 pt 2 lc rgb '#ff7f0e' title 'entropy, highest first', NaN with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' title 'equidistant E1 (every i-th)', NaN with linespoints lw 1.5 pt 4 lc rgb '#17becf' title 'equidistant E2 (spacing)', NaN with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' title 'bounding sphere', NaN with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' title 'curvature', NaN with linespoints lw 1.5 pt 7 lc rgb '#000000' title 'CGAL grid', NaN with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' title 'CGAL hierarchy', NaN with linespoints lw 1.5 pt 9 lc rgb '#9467bd' title 'CGAL WLOP', NaN with linespoints lw 1.5 pt 10 lc rgb '#e377c2' title 'CGAL random'
unset key
set border
set tics
set grid
set xlabel 'points kept (%)'
set autoscale
set logscale x
unset multiplot
set output 'chart_uniformity.png'
set multiplot layout 2,3 title 'coefficient of variation of the spacing of the result'
unset logscale y
set title 'replica_2mm'
plot 'data_replica_2mm.dat' index 0 using 1:6 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_2mm.dat' index 1 using 1:6 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_2mm.dat' index 2 using 1:6 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_2mm.dat' index 3 using 1:6 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_2mm.dat' index 4 using 1:6 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_2mm.dat' index 5 using 1:6 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_2mm.dat' index 6 using 1:6 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_2mm.dat' index 7 using 1:6 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_2mm.dat' index 8 using 1:6 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_2mm.dat' index 9 using 1:6 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'replica_1.2mm'
plot 'data_replica_1.2mm.dat' index 0 using 1:6 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_1.2mm.dat' index 1 using 1:6 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_1.2mm.dat' index 2 using 1:6 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_1.2mm.dat' index 3 using 1:6 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_1.2mm.dat' index 4 using 1:6 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_1.2mm.dat' index 5 using 1:6 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_1.2mm.dat' index 6 using 1:6 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_1.2mm.dat' index 7 using 1:6 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_1.2mm.dat' index 8 using 1:6 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_1.2mm.dat' index 9 using 1:6 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'lion'
plot 'data_lion.dat' index 0 using 1:6 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_lion.dat' index 1 using 1:6 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_lion.dat' index 2 using 1:6 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_lion.dat' index 3 using 1:6 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_lion.dat' index 4 using 1:6 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_lion.dat' index 5 using 1:6 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_lion.dat' index 6 using 1:6 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_lion.dat' index 7 using 1:6 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_lion.dat' index 8 using 1:6 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_lion.dat' index 9 using 1:6 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'fandisk'
plot 'data_fandisk.dat' index 0 using 1:6 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_fandisk.dat' index 1 using 1:6 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_fandisk.dat' index 2 using 1:6 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_fandisk.dat' index 3 using 1:6 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_fandisk.dat' index 4 using 1:6 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_fandisk.dat' index 5 using 1:6 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_fandisk.dat' index 6 using 1:6 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_fandisk.dat' index 7 using 1:6 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_fandisk.dat' index 8 using 1:6 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_fandisk.dat' index 9 using 1:6 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'b9_training'
plot 'data_b9_training.dat' index 0 using 1:6 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_b9_training.dat' index 1 using 1:6 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_b9_training.dat' index 2 using 1:6 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_b9_training.dat' index 3 using 1:6 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_b9_training.dat' index 4 using 1:6 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_b9_training.dat' index 5 using 1:6 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_b9_training.dat' index 6 using 1:6 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_b9_training.dat' index 7 using 1:6 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_b9_training.dat' index 8 using 1:6 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_b9_training.dat' index 9 using 1:6 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set key center center box font 'sans,11'
unset title
unset border
unset tics
unset grid
unset xlabel
set xrange [0:1]
set yrange [0:1]
unset logscale
plot NaN with linespoints lw 3 pt 1 lc rgb '#d62728' title 'entropy, lowest first', NaN with linespoints lw 3 pt 2 lc rgb '#ff7f0e' title 'entropy, highest first', NaN with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' title 'equidistant E1 (every i-th)', NaN with linespoints lw 1.5 pt 4 lc rgb '#17becf' title 'equidistant E2 (spacing)', NaN with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' title 'bounding sphere', NaN with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' title 'curvature', NaN with linespoints lw 1.5 pt 7 lc rgb '#000000' title 'CGAL grid', NaN with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' title 'CGAL hierarchy', NaN with linespoints lw 1.5 pt 9 lc rgb '#9467bd' title 'CGAL WLOP', NaN with linespoints lw 1.5 pt 10 lc rgb '#e377c2' title 'CGAL random'
unset key
set border
set tics
set grid
set xlabel 'points kept (%)'
set autoscale
set logscale x
unset multiplot
set output 'chart_mean_entropy.png'
set multiplot layout 2,3 title 'mean entropy of the paper (Eq. 7), bits'
unset logscale y
set title 'replica_2mm'
plot 'data_replica_2mm.dat' index 0 using 1:7 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_2mm.dat' index 1 using 1:7 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_2mm.dat' index 2 using 1:7 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_2mm.dat' index 3 using 1:7 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_2mm.dat' index 4 using 1:7 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_2mm.dat' index 5 using 1:7 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_2mm.dat' index 6 using 1:7 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_2mm.dat' index 7 using 1:7 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_2mm.dat' index 8 using 1:7 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_2mm.dat' index 9 using 1:7 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'replica_1.2mm'
plot 'data_replica_1.2mm.dat' index 0 using 1:7 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_replica_1.2mm.dat' index 1 using 1:7 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_replica_1.2mm.dat' index 2 using 1:7 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_replica_1.2mm.dat' index 3 using 1:7 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_replica_1.2mm.dat' index 4 using 1:7 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_replica_1.2mm.dat' index 5 using 1:7 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_replica_1.2mm.dat' index 6 using 1:7 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_replica_1.2mm.dat' index 7 using 1:7 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_replica_1.2mm.dat' index 8 using 1:7 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_replica_1.2mm.dat' index 9 using 1:7 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'lion'
plot 'data_lion.dat' index 0 using 1:7 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_lion.dat' index 1 using 1:7 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_lion.dat' index 2 using 1:7 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_lion.dat' index 3 using 1:7 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_lion.dat' index 4 using 1:7 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_lion.dat' index 5 using 1:7 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_lion.dat' index 6 using 1:7 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_lion.dat' index 7 using 1:7 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_lion.dat' index 8 using 1:7 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_lion.dat' index 9 using 1:7 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'fandisk'
plot 'data_fandisk.dat' index 0 using 1:7 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_fandisk.dat' index 1 using 1:7 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_fandisk.dat' index 2 using 1:7 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_fandisk.dat' index 3 using 1:7 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_fandisk.dat' index 4 using 1:7 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_fandisk.dat' index 5 using 1:7 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_fandisk.dat' index 6 using 1:7 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_fandisk.dat' index 7 using 1:7 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_fandisk.dat' index 8 using 1:7 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_fandisk.dat' index 9 using 1:7 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set title 'b9_training'
plot 'data_b9_training.dat' index 0 using 1:7 with linespoints lw 3 pt 1 lc rgb '#d62728' notitle, 'data_b9_training.dat' index 1 using 1:7 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' notitle, 'data_b9_training.dat' index 2 using 1:7 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' notitle, 'data_b9_training.dat' index 3 using 1:7 with linespoints lw 1.5 pt 4 lc rgb '#17becf' notitle, 'data_b9_training.dat' index 4 using 1:7 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' notitle, 'data_b9_training.dat' index 5 using 1:7 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' notitle, 'data_b9_training.dat' index 6 using 1:7 with linespoints lw 1.5 pt 7 lc rgb '#000000' notitle, 'data_b9_training.dat' index 7 using 1:7 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' notitle, 'data_b9_training.dat' index 8 using 1:7 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' notitle, 'data_b9_training.dat' index 9 using 1:7 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' notitle
set key center center box font 'sans,11'
unset title
unset border
unset tics
unset grid
unset xlabel
set xrange [0:1]
set yrange [0:1]
unset logscale
plot NaN with linespoints lw 3 pt 1 lc rgb '#d62728' title 'entropy, lowest first', NaN with linespoints lw 3 pt 2 lc rgb '#ff7f0e' title 'entropy, highest first', NaN with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' title 'equidistant E1 (every i-th)', NaN with linespoints lw 1.5 pt 4 lc rgb '#17becf' title 'equidistant E2 (spacing)', NaN with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' title 'bounding sphere', NaN with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' title 'curvature', NaN with linespoints lw 1.5 pt 7 lc rgb '#000000' title 'CGAL grid', NaN with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' title 'CGAL hierarchy', NaN with linespoints lw 1.5 pt 9 lc rgb '#9467bd' title 'CGAL WLOP', NaN with linespoints lw 1.5 pt 10 lc rgb '#e377c2' title 'CGAL random'
unset key
set border
set tics
set grid
set xlabel 'points kept (%)'
set autoscale
set logscale x
unset multiplot
set output 'chart_fandisk_sharp_edges.png'
set terminal pngcairo noenhanced size 1000,600 font 'sans,10'
unset logscale y
set key outside right top
set title 'fandisk: share of kept points near a sharp edge / the input share'
plot 'data_fandisk.dat' index 0 using 1:8 with linespoints lw 3 pt 1 lc rgb '#d62728' title 'entropy, lowest first', 'data_fandisk.dat' index 1 using 1:8 with linespoints lw 3 pt 2 lc rgb '#ff7f0e' title 'entropy, highest first', 'data_fandisk.dat' index 2 using 1:8 with linespoints lw 1.5 pt 3 lc rgb '#1f77b4' title 'equidistant E1 (every i-th)', 'data_fandisk.dat' index 3 using 1:8 with linespoints lw 1.5 pt 4 lc rgb '#17becf' title 'equidistant E2 (spacing)', 'data_fandisk.dat' index 4 using 1:8 with linespoints lw 1.5 pt 5 lc rgb '#2ca02c' title 'bounding sphere', 'data_fandisk.dat' index 5 using 1:8 with linespoints lw 1.5 pt 6 lc rgb '#bcbd22' title 'curvature', 'data_fandisk.dat' index 6 using 1:8 with linespoints lw 1.5 pt 7 lc rgb '#000000' title 'CGAL grid', 'data_fandisk.dat' index 7 using 1:8 with linespoints lw 1.5 pt 8 lc rgb '#7f7f7f' title 'CGAL hierarchy', 'data_fandisk.dat' index 8 using 1:8 with linespoints lw 1.5 pt 9 lc rgb '#9467bd' title 'CGAL WLOP', 'data_fandisk.dat' index 9 using 1:8 with linespoints lw 1.5 pt 10 lc rgb '#e377c2' title 'CGAL random'
