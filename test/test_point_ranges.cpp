// Tests of entropy_simplify_point_set on the point ranges users have:
// CGAL::Point_set_3 with extra properties, vectors of points or of
// (point, normal) pairs, several kernels; on real scans; and of the replica
// of the paper's Experiment I.

#include <catch2/catch.hpp>

#include "require_tbb.h"
#include "test_clouds.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/experiment_I_replica.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_set = CGAL::Point_set_3<Epick::Point_3, Epick::Vector_3>;

namespace {

std::vector<Epick::Point_3> replica_points(std::size_t board, std::size_t sphere, std::uint64_t seed)
{
  std::vector<Epick::Point_3> points;
  for (const auto& p : test_clouds::small_replica(board, sphere, 0.002, seed).points)
    points.emplace_back(p.x(), p.y(), p.z());
  return points;
}

// The kept points of a vector run, as a set of coordinates.
template <typename Point>
std::set<std::array<double, 3> > coordinates(typename std::vector<Point>::const_iterator first,
                                             typename std::vector<Point>::const_iterator beyond)
{
  std::set<std::array<double, 3> > result;
  for (auto it = first; it != beyond; ++it)
    result.insert({ double(it->x()), double(it->y()), double(it->z()) });
  return result;
}

// A scan record without a default constructor, whose point a map reads.
struct Scan_record
{
  Scan_record(const Epick::Point_3& p, int i) : point(p), id(i) {}
  Epick::Point_3 point;
  int id;
};

struct Scan_record_point_map
{
  using key_type = Scan_record;
  using value_type = Epick::Point_3;
  using reference = const Epick::Point_3&;
  using category = boost::readable_property_map_tag;
  friend reference get(const Scan_record_point_map&, const Scan_record& r) { return r.point; }
};

} // namespace

TEST_CASE("Ranges of elements without a default constructor: reordered as a vector of points is", "[kernels]")
{
  test_parallel::require_tbb();
  const std::vector<Epick::Point_3> points = replica_points(1600, 400, 8);
  std::vector<Scan_record> records;
  for (std::size_t i = 0; i < points.size(); ++i)
    records.emplace_back(points[i], int(i));
  std::vector<Epick::Point_3> expected = points;
  const auto kept = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(expected, 10,
                                                                           CGAL::parameters::select_percentage(10.));
  REQUIRE(kept - expected.begin() == 200);
  const auto first_removed = test_parallel::on_two_threads_or_more([&] {
    return CGAL::entropy_simplify_point_set<test_parallel::Parallel_tag>(
      records, 10, CGAL::parameters::select_percentage(10.).point_map(Scan_record_point_map()));
  });
  CHECK(first_removed - records.begin() == 200);
  bool same_order = true, each_once = true;
  std::vector<bool> seen(points.size(), false);
  for (std::size_t i = 0; i < records.size(); ++i)
  {
    same_order = same_order && records[i].point == expected[i];
    const std::size_t id = std::size_t(records[i].id);
    each_once = each_once && !seen[id] && points[id] == records[i].point;
    seen[id] = true;
  }
  CHECK(same_order);
  CHECK(each_once);
}

TEST_CASE("Point_set_3: extra properties follow the kept points, its normals are untouched", "[point set]")
{
  const std::vector<Epick::Point_3> points = replica_points(4000, 1000, 3);
  Point_set set;
  auto colour = set.add_property_map<std::array<unsigned char, 3> >("colour").first;
  auto original = set.add_property_map<int>("original").first;
  set.add_normal_map();
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const auto index = *set.insert(points[i]);
    colour[index] = { (unsigned char)(i % 251), (unsigned char)(i % 241), (unsigned char)(i % 239) };
    original[index] = int(i);
    set.normal(index) = Epick::Vector_3(0., 0., 7.);
  }

  const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    set, 10, CGAL::parameters::number_of_output_points(700));
  set.remove(first_removed, set.end());
  set.collect_garbage();
  REQUIRE(set.size() == 700);

  bool properties_follow = true, normals_untouched = true;
  std::set<int> kept;
  for (const auto index : set)
  {
    const int i = original[index];
    kept.insert(i);
    properties_follow = properties_follow && set.point(index) == points[std::size_t(i)] &&
                        colour[index] == std::array<unsigned char, 3>{ (unsigned char)(i % 251),
                                                                       (unsigned char)(i % 241),
                                                                       (unsigned char)(i % 239) };
    normals_untouched = normals_untouched && set.normal(index) == Epick::Vector_3(0., 0., 7.);
  }
  CHECK(properties_follow);
  CHECK(normals_untouched);
  CHECK(kept.size() == 700);

  // The same points as with a plain vector.
  std::vector<Epick::Point_3> vector = points;
  const auto it = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    vector, 10, CGAL::parameters::number_of_output_points(700));
  std::set<std::array<double, 3> > from_set;
  for (const auto index : set)
    from_set.insert({ set.point(index).x(), set.point(index).y(), set.point(index).z() });
  CHECK(from_set == coordinates<Epick::Point_3>(vector.cbegin(), std::vector<Epick::Point_3>::const_iterator(it)));
}

TEST_CASE("Point_set_3: normals are written to the map given explicitly", "[point set]")
{
  Point_set set;
  for (const auto& p : replica_points(800, 200, 4))
    set.insert(p);
  set.add_normal_map();
  const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    set, 10, CGAL::parameters::number_of_output_points(100).normal_map(set.normal_map()));
  bool unit = true;
  for (auto it = set.begin(); it != first_removed; ++it)
    unit = unit && std::abs(set.normal(*it).squared_length() - 1.) < 1e-12;
  CHECK(unit);
}

TEST_CASE("Kernels: Epick and Simple_cartesian<double> agree, float compiles and keeps the count", "[kernels]")
{
  const std::vector<Epick::Point_3> epick = replica_points(1600, 400, 6);
  std::vector<CGAL::Simple_cartesian<double>::Point_3> cartesian;
  std::vector<CGAL::Simple_cartesian<float>::Point_3> single;
  std::vector<std::pair<Epick::Point_3, Epick::Vector_3> > pairs;
  for (const auto& p : epick)
  {
    cartesian.emplace_back(p.x(), p.y(), p.z());
    single.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    pairs.emplace_back(p, Epick::Vector_3(1., 2., 3.));
  }

  std::vector<Epick::Point_3> a = epick;
  const auto ia = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(a, 10, CGAL::parameters::select_percentage(10.));
  const auto ib = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(cartesian, 10,
                                                                         CGAL::parameters::select_percentage(10.));
  CHECK(coordinates<Epick::Point_3>(a.cbegin(), std::vector<Epick::Point_3>::const_iterator(ia)) ==
        coordinates<CGAL::Simple_cartesian<double>::Point_3>(
          cartesian.cbegin(), std::vector<CGAL::Simple_cartesian<double>::Point_3>::const_iterator(ib)));

  const auto ic = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(single, 10,
                                                                         CGAL::parameters::select_percentage(10.));
  CHECK(std::size_t(ic - single.begin()) == 200);

  const auto id = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    pairs, 10,
    CGAL::parameters::select_percentage(10.).point_map(
      CGAL::First_of_pair_property_map<std::pair<Epick::Point_3, Epick::Vector_3> >()));
  CHECK(std::size_t(id - pairs.begin()) == 200);
  bool vectors_untouched = true;
  for (const auto& p : pairs)
    vectors_untouched = vectors_untouched && p.second == Epick::Vector_3(1., 2., 3.);
  CHECK(vectors_untouched);
}

TEST_CASE("Real scans from libcgal-demo: count, subset, determinism", "[real data]")
{
  test_parallel::require_tbb();
  for (const std::string name : { "points_3/kitten.xyz", "points_3/b9_training.ply", "points_3/oni.pwn" })
  {
    INFO(name);
    std::vector<Epick::Point_3> points;
    REQUIRE(CGAL::IO::read_points(std::string(ES_TEST_DATA_DIR) + "/" + name, std::back_inserter(points)));
    REQUIRE(points.size() > 1000);
    ES::Options lowest, highest;
    lowest.mode = highest.mode = ES::Mode::paper;
    highest.removal_order = ES::Removal_order::highest_entropy_first;
    for (const ES::Options& options : { ES::Options(), lowest, highest })
    {
      std::vector<Epick::Point_3> sequential = points, parallel = points;
      const auto is = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
        sequential, 10, CGAL::parameters::select_percentage(5.), options);
      const auto ip = test_parallel::on_two_threads_or_more([&] {
        return CGAL::entropy_simplify_point_set<test_parallel::Parallel_tag>(
          parallel, 10, CGAL::parameters::select_percentage(5.), options);
      });
      CHECK(std::size_t(is - sequential.begin()) == ES::internal::kept_count_from_percentage(points.size(), 5.));
      CHECK(ip - parallel.begin() == is - sequential.begin());
      CHECK(sequential == parallel);
      std::multiset<std::array<double, 3> > before, after;
      for (const auto& p : points)
        before.insert({ p.x(), p.y(), p.z() });
      for (const auto& p : sequential)
        after.insert({ p.x(), p.y(), p.z() });
      CHECK(before == after);
    }
  }
}

TEST_CASE("The replica of Experiment I", "[replica]")
{
  using Point = Epick::Point_3;
  for (double noise : { 0.002, 0.0012 })
  {
    ES::Experiment_I_setup setup;
    setup.range_noise = noise;
    std::vector<std::pair<Point, int> > replica, again;
    ES::experiment_I_replica<Point>(std::back_inserter(replica), setup);
    ES::experiment_I_replica<Point>(std::back_inserter(again), setup);
    REQUIRE(replica.size() == 182191);
    CHECK(replica == again);

    std::map<int, std::size_t> count;
    double board_squares = 0., sphere_squares = 0.;
    const Point centre(setup.sphere_x, setup.sphere_y, setup.board_distance - setup.sphere_gap);
    for (const auto& p : replica)
    {
      ++count[p.second];
      if (p.second == ES::board_label)
        board_squares += CGAL::square(p.first.z() - setup.board_distance);
      else
        sphere_squares += CGAL::square(std::sqrt(CGAL::squared_distance(p.first, centre)) - setup.sphere_radius);
    }
    CHECK(count[ES::board_label] == 147876);
    CHECK(count[ES::sphere_label] == 34315);
    // The board faces the scanner: its residuals are the range noise, shrunk by
    // the cosine of the ray's angle (at most 11 degrees). The ball's residuals
    // are the noise projected on its normals, smaller away from its centre.
    const double board_rmse = std::sqrt(board_squares / double(count[ES::board_label]));
    const double sphere_rmse = std::sqrt(sphere_squares / double(count[ES::sphere_label]));
    INFO("noise " << noise << ", board RMSE " << board_rmse << ", ball RMSE " << sphere_rmse);
    CHECK(board_rmse == Approx(noise).epsilon(0.03));
    CHECK(sphere_rmse < noise);
    CHECK(sphere_rmse > 0.5 * noise);
  }
  ES::Experiment_I_setup bad;
  bad.sphere_points = 0;
  std::vector<std::pair<Point, int> > none;
  CHECK_THROWS_AS(ES::experiment_I_replica<Point>(std::back_inserter(none), bad), std::invalid_argument);
}
