// Must not compile: neighbor_radius is a named parameter of other CGAL
// functions, which entropy_simplify_point_set() does not read. CGAL would
// ignore it silently; the package rejects it (see the test of that name).
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Simple_cartesian.h>
#include <vector>

int main()
{
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    points, 10, CGAL::parameters::number_of_output_points(10).neighbor_radius(0.1));
  return 0;
}
