set terminal pngcairo noenhanced size 1800,1720 font 'sans,10'
set output 'pictures_lion.png'
set multiplot layout 4,4 title 'lion, 20% of the points kept by each method'
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
set title 'PCL voxel grid'
splot 'points/lion__pcl_voxel_grid.txt' using 1:3:2:3 with dots lc palette
set title 'PCL uniform sampling'
splot 'points/lion__pcl_uniform_sampling.txt' using 1:3:2:3 with dots lc palette
set title 'PCL normal space sampling'
splot 'points/lion__pcl_normal_space_sampling.txt' using 1:3:2:3 with dots lc palette
set title 'Open3D voxel down-sample'
splot 'points/lion__open3d_voxel_down_sample.txt' using 1:3:2:3 with dots lc palette
set title 'Open3D farthest point'
splot 'points/lion__open3d_farthest_point.txt' using 1:3:2:3 with dots lc palette
unset multiplot
