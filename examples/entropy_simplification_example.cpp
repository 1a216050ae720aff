// Reads a point set, keeps 10% of its points by the local entropy of normal
// angles, and writes the result.

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Parallel_if_available_tag Concurrency_tag;

int main(int argc, char** argv)
{
  const std::string fname = (argc > 1) ? argv[1] : CGAL::data_file_path("points_3/kitten.xyz");
  std::vector<Point> points;
  if (!CGAL::IO::read_points(fname, std::back_inserter(points)))
  {
    std::cerr << "Error: cannot read file " << fname << std::endl;
    return EXIT_FAILURE;
  }

  // Keeps exactly ceil(10% of the points); k = 10 neighbours per point.
  const unsigned int k = 10;
  auto first_to_remove = CGAL::entropy_simplify_point_set<Concurrency_tag>(
    points, k, CGAL::parameters::select_percentage(10.));

  // How far the input lies from the kept points, over its bounding-box
  // diagonal: the range still holds every input point, the kept ones first.
  const std::vector<Point> kept(points.begin(), first_to_remove);
  const CGAL::Entropy_simplification::Quality_report quality =
    CGAL::measure_simplification_quality<Concurrency_tag>(points, kept);
  std::cout << points.size() << " points, " << kept.size() << " kept; mean distance " << quality.mean_distance
            << ", max distance " << quality.max_distance << ", point-to-plane error " << quality.point_to_plane
            << std::endl;

  points.erase(first_to_remove, points.end());

  if (!CGAL::IO::write_points("simplified.xyz", points, CGAL::parameters::stream_precision(17)))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}
