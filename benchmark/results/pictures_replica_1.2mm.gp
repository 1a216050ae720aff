set terminal pngcairo noenhanced size 1800,2150 font 'sans,10'
set output 'pictures_replica_1.2mm.png'
set multiplot layout 5,4 title 'replica_1.2mm, 10% of the points kept by each method'
unset key
unset tics
unset border
unset colorbox
set size ratio -1
set palette defined (0 '#777777', 1 '#d62728')
set cbrange [0:1]
set title 'package default'
plot 'points/replica_1.2mm__package_default.txt' using 1:2:4 with dots lc palette
set title 'default without entropy term'
plot 'points/replica_1.2mm__default_without_entropy_term.txt' using 1:2:4 with dots lc palette
set title 'entropy, lowest first'
plot 'points/replica_1.2mm__entropy__lowest_first.txt' using 1:2:4 with dots lc palette
set title 'entropy, highest first'
plot 'points/replica_1.2mm__entropy__highest_first.txt' using 1:2:4 with dots lc palette
set title 'equidistant E1 (every i-th)'
plot 'points/replica_1.2mm__equidistant_e1__every_i_th_.txt' using 1:2:4 with dots lc palette
set title 'equidistant E2 (spacing)'
plot 'points/replica_1.2mm__equidistant_e2__spacing_.txt' using 1:2:4 with dots lc palette
set title 'bounding sphere'
plot 'points/replica_1.2mm__bounding_sphere.txt' using 1:2:4 with dots lc palette
set title 'curvature'
plot 'points/replica_1.2mm__curvature.txt' using 1:2:4 with dots lc palette
set title 'CGAL grid'
plot 'points/replica_1.2mm__cgal_grid.txt' using 1:2:4 with dots lc palette
set title 'CGAL hierarchy'
plot 'points/replica_1.2mm__cgal_hierarchy.txt' using 1:2:4 with dots lc palette
set title 'CGAL WLOP'
plot 'points/replica_1.2mm__cgal_wlop.txt' using 1:2:4 with dots lc palette
set title 'CGAL random'
plot 'points/replica_1.2mm__cgal_random.txt' using 1:2:4 with dots lc palette
set title 'PCL voxel grid'
plot 'points/replica_1.2mm__pcl_voxel_grid.txt' using 1:2:4 with dots lc palette
set title 'PCL uniform sampling'
plot 'points/replica_1.2mm__pcl_uniform_sampling.txt' using 1:2:4 with dots lc palette
set title 'PCL normal space sampling'
plot 'points/replica_1.2mm__pcl_normal_space_sampling.txt' using 1:2:4 with dots lc palette
set title 'Open3D voxel down-sample'
plot 'points/replica_1.2mm__open3d_voxel_down_sample.txt' using 1:2:4 with dots lc palette
set title 'Open3D farthest point'
plot 'points/replica_1.2mm__open3d_farthest_point.txt' using 1:2:4 with dots lc palette
unset multiplot
