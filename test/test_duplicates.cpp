// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Coincident points: points equal as doubles collapse to their first copy in
// input order before either mode runs; the other copies are removed first
// and come back, in input order, only once every distinct point is kept.

#include <catch2/catch.hpp>

#include "simplification_run.h"
#include "test_clouds.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using test_runs::Point;
using test_runs::Run;
using test_runs::Vector;

namespace {

ES::Options options_of(ES::Mode mode)
{
  ES::Options options;
  options.mode = mode;
  return options;
}

// Some points with copies: after every 7th point one copy of it, and at the
// end three copies of every 50th, one of them with -0.0 for 0.0.
struct Cloud_with_copies
{
  std::vector<Point> points;
  std::vector<std::size_t> source;      // the position in `distinct` each point copies
  std::vector<std::size_t> first;       // the position in `points` of each distinct point's first copy
  std::vector<std::size_t> copies;      // positions in `points` of the later copies, ascending
};

Cloud_with_copies add_copies(const std::vector<Point>& distinct)
{
  Cloud_with_copies c;
  auto add = [&c](const Point& p, std::size_t source, bool is_first) {
    if (is_first)
      c.first.push_back(c.points.size());
    else
      c.copies.push_back(c.points.size());
    c.points.push_back(p);
    c.source.push_back(source);
  };
  for (std::size_t i = 0; i < distinct.size(); ++i)
  {
    add(distinct[i], i, true);
    if (i % 7 == 0)
      add(distinct[i], i, false);
  }
  for (std::size_t i = 0; i < distinct.size(); i += 50)
    for (int copy = 0; copy < 3; ++copy)
    {
      const Point& p = distinct[i];
      // -0.0 == 0.0: the zero coordinate of point 0 is written both ways
      add(copy == 2 && p.x() == 0. ? Point(-0., p.y(), p.z()) : p, i, false);
    }
  return c;
}

std::vector<Point> distinct_surface()
{
  std::vector<Point> points = test_clouds::wavy_surface(1500, 0.003, 31).points;
  points[0] = Point(0., points[0].y(), points[0].z());
  return points;
}

} // namespace

TEST_CASE("Copies go first, the last first: the distinct points simplify as if alone", "[duplicates]")
{
  const std::vector<Point> distinct = distinct_surface();
  const Cloud_with_copies cloud = add_copies(distinct);
  REQUIRE(cloud.copies.size() == 215 + 90);
  for (ES::Mode mode : { ES::Mode::weighted_elimination, ES::Mode::paper })
    for (std::size_t target : { std::size_t(150), std::size_t(700) })
    {
      INFO("mode " << int(mode) << ", target " << target);
      const auto count = CGAL::parameters::number_of_output_points(target);
      const Run alone = test_runs::simplify_with_normals(distinct, 10, count, options_of(mode));
      const Run with_copies = test_runs::simplify_with_normals(cloud.points, 10, count, options_of(mode));

      std::vector<std::size_t> expected(cloud.copies.rbegin(), cloud.copies.rend());
      for (std::size_t i : test_runs::removal_order(alone))
        expected.push_back(cloud.first[i]);
      CHECK(test_runs::removal_order(with_copies) == expected);
      CHECK(test_runs::is_permutation_of_input(with_copies));

      bool same_normals = true;
      for (std::size_t i : test_runs::kept_positions(alone))
        same_normals = same_normals && with_copies.normals[cloud.first[i]] == alone.normals[i];
      CHECK(same_normals);
    }
}

TEST_CASE("Copies come back in input order once every distinct point is kept", "[duplicates]")
{
  const std::vector<Point> distinct = distinct_surface();
  const Cloud_with_copies cloud = add_copies(distinct);
  for (ES::Mode mode : { ES::Mode::weighted_elimination, ES::Mode::paper })
  {
    INFO("mode " << int(mode));
    const std::size_t target = distinct.size() + 3;
    const Run run =
      test_runs::simplify_with_normals(cloud.points, 10, CGAL::parameters::number_of_output_points(target), options_of(mode));
    REQUIRE(run.kept == target);
    std::set<std::size_t> expected(cloud.first.begin(), cloud.first.end());
    expected.insert(cloud.copies.begin(), cloud.copies.begin() + 3);
    CHECK(test_runs::kept_positions(run) == expected);
    // a kept copy has the normal of its first copy, a defined one
    for (std::size_t j = 0; j < 3; ++j)
    {
      const std::size_t copy = cloud.copies[j];
      const Vector& n = run.normals[copy];
      CHECK(n == run.normals[cloud.first[cloud.source[copy]]]);
      CHECK(n.squared_length() == Approx(1.));
    }
  }
}

TEST_CASE("Points 1e-12 apart are distinct, and fewer than k + 1 distinct points is an error", "[duplicates]")
{
  std::vector<Point> six;
  for (int i = 0; i < 6; ++i)
    six.emplace_back(0.1 * i, 0.3 * (i % 2), 0.05 * i * i);
  std::vector<Point> near = six, equal = six;
  for (const Point& p : six)
  {
    near.emplace_back(p.x() + 1e-12, p.y(), p.z());
    equal.push_back(p);
  }
  for (ES::Mode mode : { ES::Mode::weighted_elimination, ES::Mode::paper })
  {
    INFO("mode " << int(mode));
    const auto count = CGAL::parameters::number_of_output_points(11);
    // 12 distinct points: k = 10 has its neighbours
    CHECK(test_runs::simplify_with_normals(near, 10, count, options_of(mode)).kept == 11);
    std::vector<Point> range = equal;
    CHECK_THROWS_WITH(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(range, 10, count, options_of(mode)),
                      Catch::Contains("at least k + 1 distinct points; the range has 6 (of 12 points)"));
    CHECK(range == equal);
  }
}

TEST_CASE("200,000 copies of one point among 20,000: an exact count, at most one copy kept", "[duplicates]")
{
  std::vector<Point> points = test_clouds::wavy_surface(20000, 0.002, 41).points;
  const Point copied = points[123];
  points.insert(points.begin() + 10000, 200000, copied);
  for (ES::Mode mode : { ES::Mode::weighted_elimination, ES::Mode::paper })
  {
    INFO("mode " << int(mode));
    const Run run =
      test_runs::simplify_with_normals(points, 10, CGAL::parameters::number_of_output_points(2000), options_of(mode));
    REQUIRE(run.kept == 2000);
    CHECK(test_runs::is_permutation_of_input(run));
    std::size_t copies_kept = 0;
    for (std::size_t i : test_runs::kept_positions(run))
      copies_kept += points[i] == copied ? 1 : 0;
    CHECK(copies_kept <= 1);
  }
}

// The first equal point of each point, against a map from coordinates that
// shares nothing with the buckets: on lattice points with many copies and
// zeros written as -0.0, at sizes around the number of buckets' steps, with
// the package's key and with one key for all points, as keys made to collide
// would give, so that only the coordinates tell points apart.
TEST_CASE("Each point's first equal point is that of a map from coordinates", "[duplicates]")
{
  namespace ESI = ES::internal;
  ESI::Portable_random random(41);
  for (std::size_t n : { 0, 1, 2, 5, 17, 1000, 60000, 200000 })
  {
    ESI::Array<ESI::Working_point> points;
    for (std::size_t i = 0; i < n; ++i)
    {
      auto coordinate = [&random] {
        const double c = double(random.below(5)) - 2.;
        return c == 0. && random.below(2) == 0 ? -0. : c;
      };
      const double x = coordinate(), y = coordinate(), z = coordinate();
      points.emplace_back(x, y, i % 3 == 0 ? z : 0.25 * double(i % 97));
    }
    std::map<std::tuple<double, double, double>, ESI::Index> first_of;
    std::vector<ESI::Index> expected;
    for (std::size_t i = 0; i < n; ++i)
      expected.push_back(first_of.emplace(std::make_tuple(points[i].x(), points[i].y(), points[i].z()), ESI::Index(i))
                           .first->second);
    auto same_key = [](const ESI::Working_point&) { return std::uint64_t(42); };
    const ESI::Array<ESI::Index> sequential = ESI::first_equal_points<CGAL::Sequential_tag>(points);
    const ESI::Array<ESI::Index> colliding = ESI::first_equal_points<CGAL::Sequential_tag>(points, same_key);
    CHECK(std::vector<ESI::Index>(sequential.begin(), sequential.end()) == expected);
    CHECK(std::vector<ESI::Index>(colliding.begin(), colliding.end()) == expected);
#ifdef CGAL_LINKED_WITH_TBB
    const ESI::Array<ESI::Index> parallel = ESI::first_equal_points<CGAL::Parallel_tag>(points);
    CHECK(std::vector<ESI::Index>(parallel.begin(), parallel.end()) == expected);
#endif
    if (n >= 60000)
      CHECK(first_of.size() < 20000); // copies are the rule, not the exception
  }
}
