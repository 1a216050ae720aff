// Simplifies a CGAL::Point_set_3 read from a PLY file: its extra properties
// (here colours and labels) follow the kept points, and the normals estimated
// on the kept points are stored in the point set.

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> Point_set;
namespace ES = CGAL::Entropy_simplification;

int main(int argc, char** argv)
{
  const std::string fname = (argc > 1) ? argv[1] : CGAL::data_file_path("points_3/b9_training.ply");
  Point_set points;
  if (!CGAL::IO::read_point_set(fname, points))
  {
    std::cerr << "Error: cannot read file " << fname << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points with the properties:";
  for (const std::string& name : points.properties())
    std::cout << " " << name;
  std::cout << std::endl;

  // The package's own options: here, the default mode with normals
  // estimated by jet fitting, and features kept up to 5 times denser than
  // flat regions.
  ES::Options options;
  options.normal_estimation = ES::Normal_estimation::jet;
  options.feature_weight = 4.;

  // Normals are written only to a map given explicitly.
  points.add_normal_map();
  auto first_to_remove = CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
    points, 12,
    CGAL::parameters::number_of_output_points(5000).normal_map(points.normal_map()),
    options);
  points.remove(first_to_remove, points.end());
  points.collect_garbage();
  std::cout << points.size() << " points kept" << std::endl;

  if (!CGAL::IO::write_point_set("simplified.ply", points))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}
