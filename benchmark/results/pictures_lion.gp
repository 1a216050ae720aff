set terminal pngcairo noenhanced size 1800,1290 font 'sans,10'
set output 'pictures_lion.png'
set multiplot layout 3,4 title 'lion, 20% of the points kept by each method'
unset key
unset tics
unset border
unset colorbox
set view equal xyz
set view 80,30,1.4
set palette rgb 33,13,10
set title 'package default'
splot 'points/lion__package_default.txt' using 1:3:2:3 with dots lc palette
set title 'default without entropy term'
splot 'points/lion__default_without_entropy_term.txt' using 1:3:2:3 with dots lc palette
set title 'entropy, lowest first'
splot 'points/lion__entropy__lowest_first.txt' using 1:3:2:3 with dots lc palette
set title 'entropy, highest first'
splot 'points/lion__entropy__highest_first.txt' using 1:3:2:3 with dots lc palette
set title 'equidistant E1 (every i-th)'
splot 'points/lion__equidistant_e1__every_i_th_.txt' using 1:3:2:3 with dots lc palette
set title 'equidistant E2 (spacing)'
splot 'points/lion__equidistant_e2__spacing_.txt' using 1:3:2:3 with dots lc palette
set title 'bounding sphere'
splot 'points/lion__bounding_sphere.txt' using 1:3:2:3 with dots lc palette
set title 'curvature'
splot 'points/lion__curvature.txt' using 1:3:2:3 with dots lc palette
set title 'CGAL grid'
splot 'points/lion__cgal_grid.txt' using 1:3:2:3 with dots lc palette
set title 'CGAL hierarchy'
splot 'points/lion__cgal_hierarchy.txt' using 1:3:2:3 with dots lc palette
set title 'CGAL random'
splot 'points/lion__cgal_random.txt' using 1:3:2:3 with dots lc palette
unset multiplot
