#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/experiment_I_replica.h>
#include <CGAL/Simple_cartesian.h>

#include <iostream>
#include <vector>

int main()
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  CGAL::Entropy_simplification::Experiment_I_setup setup;
  setup.board_points = 800;
  setup.sphere_points = 200;
  std::vector<std::pair<Point, int> > replica;
  CGAL::Entropy_simplification::experiment_I_replica<Point>(std::back_inserter(replica), setup);
  std::vector<Point> points;
  for (const auto& p : replica)
    points.push_back(p.first);
  const auto it = CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
    points, 10, CGAL::parameters::number_of_output_points(100));
  std::cout << "kept " << (it - points.begin()) << " of " << points.size() << std::endl;
  return (it - points.begin()) == 100 ? 0 : 1;
}
