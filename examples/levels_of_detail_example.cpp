// Levels of detail from one run: every point of a CGAL::Point_set_3 gets its
// rank and its importance as properties. The points of rank below m are a
// simplification to m points, for every m: a viewer streams them by rank,
// and the exact level (here 5%) is the direct call's result.

#include <CGAL/Entropy_simplification/compute_entropy_importance.h>
#include <CGAL/Entropy_simplification/entropy_simplification_ranks.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3> Point_set;

int main(int argc, char** argv)
{
  const std::string fname = (argc > 1) ? argv[1] : CGAL::data_file_path("points_3/b9_training.ply");
  Point_set points;
  if (!CGAL::IO::read_point_set(fname, points) || points.size() < 100)
  {
    std::cerr << "Error: cannot read at least 100 points from " << fname << std::endl;
    return EXIT_FAILURE;
  }

  // The importance goes to a property of the points; the ranks, a
  // permutation, come in the order of the range.
  Point_set::Property_map<double> importance = points.add_property_map<double>("importance", 0.).first;
  CGAL::compute_entropy_importance<CGAL::Parallel_if_available_tag>(points, 10, importance);
  std::vector<std::size_t> ranks;
  CGAL::entropy_simplification_ranks<CGAL::Parallel_if_available_tag>(points, 10, std::back_inserter(ranks),
                                                                      CGAL::parameters::select_percentage(5.));

  Point_set::Property_map<unsigned int> rank_map = points.add_property_map<unsigned int>("rank", 0).first;
  std::vector<Point_set::Index> by_rank(points.size());
  std::size_t position = 0;
  for (Point_set::Index i : points)
  {
    put(rank_map, i, static_cast<unsigned int>(ranks[position]));
    by_rank[ranks[position]] = i;
    ++position;
  }

  // Each level is a prefix of the points by rank.
  for (double percentage : { 1., 5., 20. })
  {
    std::vector<Kernel::Point_3> level;
    for (std::size_t r = 0; r < std::size_t(double(points.size()) * percentage / 100.); ++r)
      level.push_back(points.point(by_rank[r]));
    const CGAL::Entropy_simplification::Quality_report report =
      CGAL::measure_simplification_quality<CGAL::Parallel_if_available_tag>(points, level);
    std::cout << percentage << "%: " << level.size() << " points, mean distance " << report.mean_distance
              << " of the diagonal" << std::endl;
  }

  // The rank and the importance are PLY properties of every point.
  if (!CGAL::IO::write_point_set("levels_of_detail.ply", points))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}
