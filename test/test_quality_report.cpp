// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// measure_simplification_quality() against a reference written from its
// documentation: linear scans, and planes from Eigen's iterative solver.

#include <catch2/catch.hpp>

#include "require_tbb.h"
#include "test_clouds.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using test_clouds::Point;
using Exact = CGAL::Exact_predicates_inexact_constructions_kernel;

namespace {

double distance(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

// The kept points by distance to p, ties to the first in the range.
std::vector<std::size_t> kept_by_distance(const std::vector<Point>& kept, const Point& p)
{
  std::vector<std::size_t> order(kept.size());
  for (std::size_t j = 0; j < kept.size(); ++j)
    order[j] = j;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return CGAL::squared_distance(p, kept[a]) < CGAL::squared_distance(p, kept[b]);
  });
  return order;
}

ES::Quality_report reference_report(const std::vector<Point>& input, const std::vector<Point>& kept)
{
  ES::Quality_report r;
  r.input_size = input.size();
  r.kept_size = kept.size();
  Eigen::Vector3d low = Eigen::Vector3d::Constant(HUGE_VAL), high = -low;
  for (const Point& p : input)
  {
    const Eigen::Vector3d v(p.x(), p.y(), p.z());
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  r.diagonal = (high - low).norm();
  const double unit = r.diagonal > 0. ? r.diagonal : 1.;
  double sum = 0., squares = 0.;
  for (const Point& p : input)
  {
    const std::size_t q = kept_by_distance(kept, p).front();
    const double d = distance(p, kept[q]);
    sum += d;
    r.max_distance = (std::max)(r.max_distance, d);
    if (kept.size() < 3)
      continue;
    // the plane of the 10 kept points nearest q, q first
    std::vector<std::size_t> near = kept_by_distance(kept, kept[q]);
    near.erase(std::find(near.begin(), near.end(), q));
    near.insert(near.begin(), q);
    near.resize((std::min)(near.size(), std::size_t(10)));
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (std::size_t j : near)
      centroid += Eigen::Vector3d(kept[j].x(), kept[j].y(), kept[j].z());
    centroid /= double(near.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (std::size_t j : near)
    {
      const Eigen::Vector3d e = Eigen::Vector3d(kept[j].x(), kept[j].y(), kept[j].z()) - centroid;
      covariance += e * e.transpose();
    }
    const Eigen::Vector3d v = Eigen::Vector3d(p.x(), p.y(), p.z()) - centroid;
    // points that coincide or lie on one line: the distance to them
    const auto distinct = std::find_if(near.begin(), near.end(), [&](std::size_t j) { return kept[j] != kept[q]; });
    const bool on_a_line =
      distinct != near.end() && std::all_of(near.begin(), near.end(), [&](std::size_t j) {
        return CGAL::collinear(Exact::Point_3(kept[q].x(), kept[q].y(), kept[q].z()),
                               Exact::Point_3(kept[*distinct].x(), kept[*distinct].y(), kept[*distinct].z()),
                               Exact::Point_3(kept[j].x(), kept[j].y(), kept[j].z()));
      });
    const Point& along = distinct == near.end() ? kept[q] : kept[*distinct];
    const Eigen::Vector3d line(along.x() - kept[q].x(), along.y() - kept[q].y(), along.z() - kept[q].z());
    const Eigen::Vector3d normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
    const double plane_distance = distinct == near.end() ? distance(p, kept[q])
                                  : on_a_line            ? v.cross(line).norm() / line.norm()
                                                         : std::abs(normal.dot(v));
    squares += plane_distance * plane_distance;
  }
  r.mean_distance = sum / double(input.size()) / unit;
  r.max_distance /= unit;
  r.point_to_plane =
    kept.size() < 3 ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(squares / double(input.size())) / unit;
  return r;
}

template <typename ConcurrencyTag>
void require_equal_to_reference(const std::vector<Point>& input, const std::vector<Point>& kept)
{
  const ES::Quality_report r = CGAL::measure_simplification_quality<ConcurrencyTag>(input, kept);
  const ES::Quality_report e = reference_report(input, kept);
  REQUIRE(r.input_size == e.input_size);
  REQUIRE(r.kept_size == e.kept_size);
  REQUIRE(r.diagonal == Approx(e.diagonal).epsilon(1e-14));
  REQUIRE(r.max_distance == Approx(e.max_distance).epsilon(1e-14));
  REQUIRE(r.mean_distance == Approx(e.mean_distance).epsilon(1e-12));
  if (std::isnan(e.point_to_plane))
    REQUIRE(std::isnan(r.point_to_plane));
  else
    REQUIRE(r.point_to_plane == Approx(e.point_to_plane).epsilon(1e-8));
}

} // namespace

TEST_CASE("Quality report: equals the reference, on simplifications and on points that moved", "[quality report]")
{
  test_parallel::require_tbb();
  for (const test_clouds::Cloud& cloud :
       { test_clouds::small_replica(1500, 500, 0.002, 3), test_clouds::wavy_surface(1500, 0.01, 8) })
  {
    INFO(cloud.name);
    for (double percentage : { 1., 10., 50. })
    {
      std::vector<Point> points = cloud.points;
      const auto first_removed =
        CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(points, 10,
                                                                CGAL::parameters::select_percentage(percentage));
      const std::vector<Point> kept(points.begin(), first_removed);
      require_equal_to_reference<CGAL::Sequential_tag>(cloud.points, kept);
      test_parallel::on_two_threads_or_more(
        [&] { require_equal_to_reference<test_parallel::Parallel_tag>(cloud.points, kept); });
    }
    // kept points that are not input points, with copies among them: a
    // method that moves points is measured alike
    std::vector<Point> moved;
    for (std::size_t i = 0; i < cloud.points.size(); i += 7)
      moved.push_back(cloud.points[i] + CGAL::Simple_cartesian<double>::Vector_3(0.001, -0.002, 0.0005));
    moved.push_back(moved.front());
    moved.push_back(moved.front());
    require_equal_to_reference<CGAL::Sequential_tag>(cloud.points, moved);
    test_parallel::on_two_threads_or_more(
      [&] { require_equal_to_reference<test_parallel::Parallel_tag>(cloud.points, moved); });
  }
}

TEST_CASE("Quality report: copies among the kept points, in any number", "[quality report][duplicates]")
{
  test_parallel::require_tbb();
  const std::vector<Point> input = test_clouds::wavy_surface(1500, 0.01, 5).points;
  std::vector<Point> kept;
  for (std::size_t i = 0; i < input.size(); i += 5)
    kept.push_back(input[i]);
  // groups of copies on either side of the ten points of a plane, and one
  // larger, so that a kept point's neighbours are some, all or none of them
  std::size_t group = 0;
  for (std::size_t copies : { 1, 8, 9, 10, 11, 25, 2500 })
  {
    const Point copied = kept[40 * group + 1];
    kept.insert(kept.end() - std::ptrdiff_t(3 * group), copies, copied);
    ++group;
  }
  require_equal_to_reference<CGAL::Sequential_tag>(input, kept);
  test_parallel::on_two_threads_or_more(
    [&] { require_equal_to_reference<test_parallel::Parallel_tag>(input, kept); });

  // 200,000 more copies of the point that has 2,500 are measured as these
  // were: each copy visited the others in each search, for minutes
  const ES::Quality_report before = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input, kept);
  std::vector<Point> many = kept;
  many.insert(many.begin() + 300, 200000, kept[241]);
  const ES::Quality_report after = test_parallel::on_two_threads_or_more(
    [&] { return CGAL::measure_simplification_quality<test_parallel::Parallel_tag>(input, many); });
  REQUIRE(after.kept_size == kept.size() + 200000);
  REQUIRE(after.mean_distance == before.mean_distance);
  REQUIRE(after.max_distance == before.max_distance);
  REQUIRE(after.point_to_plane == before.point_to_plane);
}

TEST_CASE("Quality report: the sequential and parallel reports are equal to the last bit", "[quality report]")
{
  test_parallel::require_tbb();
  const test_clouds::Cloud cloud = test_clouds::wavy_surface(20000, 0.01, 4);
  std::vector<Point> points = cloud.points;
  const auto first_removed =
    CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(points, 10,
                                                                       CGAL::parameters::select_percentage(5.));
  const std::vector<Point> kept(points.begin(), first_removed);
  const ES::Quality_report s = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(cloud.points, kept);
  const ES::Quality_report p = test_parallel::on_two_threads_or_more(
    [&] { return CGAL::measure_simplification_quality<test_parallel::Parallel_tag>(cloud.points, kept); });
  REQUIRE(s.mean_distance == p.mean_distance);
  REQUIRE(s.max_distance == p.max_distance);
  REQUIRE(s.point_to_plane == p.point_to_plane);
  // a Point_set_3 is measured through its own point map
  CGAL::Point_set_3<Point> input_set, kept_set;
  for (const Point& p : cloud.points)
    input_set.insert(p);
  for (const Point& p : kept)
    kept_set.insert(p);
  const ES::Quality_report from_sets = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input_set, kept_set);
  REQUIRE(from_sets.mean_distance == s.mean_distance);
  REQUIRE(from_sets.point_to_plane == s.point_to_plane);
  // keeping every point is perfect on every measure but the planes'
  const ES::Quality_report all = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(cloud.points, cloud.points);
  REQUIRE(all.mean_distance == 0.);
  REQUIRE(all.max_distance == 0.);
  REQUIRE(all.point_to_plane < s.point_to_plane);
}

TEST_CASE("Quality report: bad input gets a documented behaviour", "[quality report][bad input]")
{
  const std::vector<Point> input = test_clouds::wavy_surface(200, 0.01, 2).points;
  const std::vector<Point> none;
  REQUIRE_THROWS_AS(CGAL::measure_simplification_quality<CGAL::Sequential_tag>(none, input), std::invalid_argument);
  REQUIRE_THROWS_AS(CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input, none), std::invalid_argument);
  std::vector<Point> with_nan = input;
  with_nan[17] = Point(0., std::numeric_limits<double>::quiet_NaN(), 0.);
  REQUIRE_THROWS_AS(CGAL::measure_simplification_quality<CGAL::Sequential_tag>(with_nan, input),
                    std::invalid_argument);
  REQUIRE_THROWS_AS(CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input, with_nan),
                    std::invalid_argument);

  // distinct kept points too near to be told apart, which every search
  // among them would visit: an error, as for the simplification
  std::vector<Point> cluster = input;
  for (int i = 0; i < 3000; ++i)
    cluster.emplace_back(1e-200 * (i % 17), 1e-200 * (i % 13), 1e-200 * i);
  REQUIRE_THROWS_WITH(CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input, cluster),
                      Catch::Contains("closer than about 1.5e-154"));

  // one or two kept points span no plane
  for (std::size_t m : { 1, 2 })
  {
    const std::vector<Point> few(input.begin(), input.begin() + std::ptrdiff_t(m));
    const ES::Quality_report r = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input, few);
    REQUIRE(std::isnan(r.point_to_plane));
    REQUIRE(r.max_distance > 0.);
    require_equal_to_reference<CGAL::Sequential_tag>(input, few);
  }
  // kept points on one line span no plane: the distance to the line stands
  // for the plane's (5 from the line for the third input point, by hand)
  const std::vector<Point> corners = { Point(0., 0., 0.), Point(2., 0., 0.), Point(1., 3., 4.) };
  const std::vector<Point> on_a_line = { Point(0., 0., 0.), Point(1., 0., 0.), Point(2., 0., 0.) };
  REQUIRE(CGAL::measure_simplification_quality<CGAL::Sequential_tag>(corners, on_a_line).point_to_plane ==
          Approx(std::sqrt(25. / 3.) / std::sqrt(29.)).epsilon(1e-15));
  // at any scale the package takes (squares of lengths near 1e150 or
  // 1e-150 would overflow or underflow)
  for (double scale : { std::ldexp(1., 450), std::ldexp(1., -450) })
  {
    std::vector<Point> scaled_corners, scaled_line;
    for (const Point& p : corners)
      scaled_corners.emplace_back(p.x() * scale, p.y() * scale, p.z() * scale);
    for (const Point& p : on_a_line)
      scaled_line.emplace_back(p.x() * scale, p.y() * scale, p.z() * scale);
    REQUIRE(CGAL::measure_simplification_quality<CGAL::Sequential_tag>(scaled_corners, scaled_line).point_to_plane ==
            Approx(std::sqrt(25. / 3.) / std::sqrt(29.)).epsilon(1e-15));
  }
  require_equal_to_reference<CGAL::Sequential_tag>(input, on_a_line);
  // kept points that all coincide: the distance to them stands for the plane's
  const std::vector<Point> same(5, input[3]);
  require_equal_to_reference<CGAL::Sequential_tag>(input, same);
  // an input whose points all coincide: distances undivided
  const std::vector<Point> one_place(50, Point(1., 2., 3.));
  const std::vector<Point> elsewhere = { Point(1., 2., 4.), Point(1., 2., 5.), Point(1., 3., 4.) };
  const ES::Quality_report r = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(one_place, elsewhere);
  REQUIRE(r.diagonal == 0.);
  REQUIRE(r.mean_distance == 1.);
  REQUIRE(r.max_distance == 1.);
  require_equal_to_reference<CGAL::Sequential_tag>(one_place, elsewhere);
}
