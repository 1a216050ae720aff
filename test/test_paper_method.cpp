// Tests of the paper's method (Mode::paper): the numeric routines against
// hand-computed values, the progressive removal against a brute-force
// reference, and the guarantees of entropy_simplify_point_set in that mode
// (count, subset, permutation, progressive prefixes, callback, determinism,
// bad input).

#include <catch2/catch.hpp>

#include "brute_force_reference.h"
#include "require_tbb.h"
#include "simplification_run.h"
#include "test_clouds.h"

#include <CGAL/Entropy_simplification/compute_entropy_importance.h>
#include <CGAL/Entropy_simplification/compute_mean_normal_angle_entropy.h>
#include <CGAL/Entropy_simplification/entropy_simplification_ranks.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/pca_estimate_normals.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using ES::internal::Angle_term;

namespace {

using test_runs::kept_positions;
using test_runs::paper_mode;
using test_runs::Run;

template <typename Tag = CGAL::Sequential_tag, typename NP>
Run paper_simplify(const std::vector<Point>& points, unsigned int k, const NP& np,
                   const ES::Options& options = paper_mode())
{
  return test_runs::simplify<Tag>(points, k, np, options);
}

bool is_permutation_of_input(const Run& run, const std::vector<Point>& points)
{
  return run.order.size() == points.size() && test_runs::is_permutation_of_input(run);
}

double entropy_of(const std::vector<double>& angles)
{
  return ES::internal::angle_entropy(angles.size(), [&](std::size_t i) {
    return ES::internal::make_angle_term(angles[i]);
  });
}

} // namespace

TEST_CASE("Eq. 5: entropy of hand-computed angle sets", "[entropy]")
{
  const unsigned int k = 10;
  SECTION("all angles equal give log(k + 1)")
  {
    for (double theta : { 1e-9, 0.3, 1.5707963267948966 })
      CHECK(entropy_of(std::vector<double>(k + 1, theta)) == Approx(std::log(double(k + 1))).epsilon(1e-12));
  }
  SECTION("zero angles carry no probability: 0 log 0 = 0")
  {
    // two equal non-zero angles and nine zeros: H = log 2
    std::vector<double> angles(k + 1, 0.);
    angles[3] = angles[7] = 0.4;
    CHECK(entropy_of(angles) == Approx(std::log(2.)).epsilon(1e-12));
    // a single non-zero angle: H = 0
    std::vector<double> single(k + 1, 0.);
    single[0] = 1.;
    CHECK(std::abs(entropy_of(single)) < 1e-15);
  }
  SECTION("all angles zero give 0")
  {
    CHECK(entropy_of(std::vector<double>(k + 1, 0.)) == 0.);
  }
  SECTION("unequal angles, computed by hand")
  {
    // P = (1/4, 3/4): H = -(1/4 log 1/4 + 3/4 log 3/4)
    const double expected = -(0.25 * std::log(0.25) + 0.75 * std::log(0.75));
    CHECK(entropy_of({ 0.2, 0.6 }) == Approx(expected).epsilon(1e-12));
    // P = (1/6, 2/6, 3/6)
    const double p[3] = { 1. / 6., 2. / 6., 3. / 6. };
    CHECK(entropy_of({ 0.1, 0.2, 0.3 }) ==
          Approx(-(p[0] * std::log(p[0]) + p[1] * std::log(p[1]) + p[2] * std::log(p[2]))).epsilon(1e-12));
  }
}

TEST_CASE("Eq. 4: the normal angle is the angle to the reference plane", "[entropy]")
{
  using ES::internal::normal_angle;
  const ES::internal::Working_vector z(0., 0., 1.);
  CHECK(normal_angle({ 0., 0., 3. }, z) == Approx(1.5707963267948966).epsilon(1e-15));
  CHECK(normal_angle({ 0., 0., -1. }, z) == Approx(1.5707963267948966).epsilon(1e-15));
  CHECK(normal_angle({ 2., 0., 0. }, z) == 0.);
  CHECK(normal_angle({ 1., 0., 1. }, z) == Approx(0.7853981633974483).epsilon(1e-15));
  CHECK(normal_angle({ 1., 1., std::sqrt(6.) }, z) == Approx(std::asin(std::sqrt(6.) / std::sqrt(8.))).epsilon(1e-14));
  CHECK(normal_angle(CGAL::NULL_VECTOR, z) == 0.);
}

TEST_CASE("Normals agree with CGAL's pca_estimate_normals and jet_estimate_normals", "[normals]")
{
  // Nothing removed: the normal map receives the normals of the whole cloud.
  const std::vector<Point> points = test_clouds::wavy_surface(2000, 0.002, 11).points;
  for (ES::Normal_estimation method : { ES::Normal_estimation::pca, ES::Normal_estimation::jet })
  {
    const unsigned int k = 12;
    std::vector<std::pair<Point, Vector> > ours, cgal;
    for (const Point& p : points)
    {
      ours.emplace_back(p, CGAL::NULL_VECTOR);
      cgal.emplace_back(p, CGAL::NULL_VECTOR);
    }
    ES::Options options = paper_mode();
    options.normal_estimation = method;
    const auto pm = CGAL::First_of_pair_property_map<std::pair<Point, Vector> >();
    const auto nm = CGAL::Second_of_pair_property_map<std::pair<Point, Vector> >();
    const auto it = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
      ours, k, CGAL::parameters::number_of_output_points(points.size()).point_map(pm).normal_map(nm), options);
    REQUIRE(it == ours.end());
    if (method == ES::Normal_estimation::pca)
      CGAL::pca_estimate_normals<CGAL::Sequential_tag>(cgal, k, CGAL::parameters::point_map(pm).normal_map(nm));
    else
      CGAL::jet_estimate_normals<CGAL::Sequential_tag>(cgal, k, CGAL::parameters::point_map(pm).normal_map(nm));

    double worst = 0.;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      REQUIRE(ours[i].first == cgal[i].first);
      const Vector a = ours[i].second, b = cgal[i].second;
      const double sine = std::sqrt(CGAL::cross_product(a, b).squared_length() /
                                    (a.squared_length() * b.squared_length()));
      worst = (std::max)(worst, sine);
    }
    INFO("normal estimation " << int(method));
    CHECK(worst < 1e-7);
  }
}

TEST_CASE("The removal sequence equals a brute-force recomputation after every removal", "[brute force]")
{
  const std::vector<test_clouds::Cloud> clouds = {
    test_clouds::small_replica(160, 40, 0.002, 1), test_clouds::wavy_surface(200, 0.01, 2),
    test_clouds::cube_volume(150, 3), test_clouds::bent_grid(14), test_clouds::with_duplicates(80, 4)
  };
  for (const test_clouds::Cloud& cloud : clouds)
    for (ES::Removal_order order : { ES::Removal_order::lowest_entropy_first, ES::Removal_order::highest_entropy_first })
      for (ES::Normal_estimation method : { ES::Normal_estimation::pca, ES::Normal_estimation::jet })
      {
        ES::Options options = paper_mode();
        options.removal_order = order;
        options.normal_estimation = method;
        const unsigned int k = 8;
        const std::size_t target = cloud.points.size() / 5;
        INFO(cloud.name << ", order " << int(order) << ", normals " << int(method));

        const auto reference = brute_force::removal_sequence(cloud.points, k, target, options);
        using Record = std::tuple<Point, std::size_t, Vector>;
        std::vector<Record> range;
        for (std::size_t i = 0; i < cloud.points.size(); ++i)
          range.emplace_back(cloud.points[i], i, CGAL::NULL_VECTOR);
        const auto it = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
          range, k,
          CGAL::parameters::number_of_output_points(target)
            .point_map(CGAL::Nth_of_tuple_property_map<0, Record>())
            .normal_map(CGAL::Nth_of_tuple_property_map<2, Record>()),
          options);

        std::vector<std::size_t> removal_order;
        for (auto e = range.rbegin(); e.base() != it; ++e)
          removal_order.push_back(std::get<1>(*e));
        CHECK(removal_order == reference.first);

        bool same_normals = true;
        for (auto e = range.begin(); e != it; ++e)
          same_normals = same_normals && std::get<2>(*e) == reference.second.normals[std::get<1>(*e)];
        CHECK(same_normals);
      }
}

TEST_CASE("Exactly the requested number of points is kept, as a subset, nothing lost", "[guarantees]")
{
  const std::vector<Point> points = test_clouds::small_replica(1600, 400, 0.002, 5).points;
  for (std::size_t target : { std::size_t(11), std::size_t(12), std::size_t(57), std::size_t(200),
                              std::size_t(1000), std::size_t(1999), std::size_t(2000), std::size_t(5000) })
  {
    INFO("target " << target);
    const Run run = paper_simplify(points, 10, CGAL::parameters::number_of_output_points(target));
    CHECK(run.kept == (std::min)(target, points.size()));
    CHECK(is_permutation_of_input(run, points));
  }
  for (double percentage : { 0.55, 1., 7., 10., 33.3, 50., 99.99, 100. })
  {
    INFO("percentage " << percentage);
    const Run run = paper_simplify(points, 10, CGAL::parameters::select_percentage(percentage));
    CHECK(run.kept == ES::internal::kept_count_from_percentage(points.size(), percentage));
    CHECK(is_permutation_of_input(run, points));
  }
}

TEST_CASE("The rounding of a percentage", "[guarantees]")
{
  using ES::internal::kept_count_from_percentage;
  CHECK(kept_count_from_percentage(182191, 10.) == 18220); // the paper's Table 2
  CHECK(kept_count_from_percentage(100, 7.) == 7);        // 100 * 7.0 / 100 is not exactly 7
  CHECK(kept_count_from_percentage(1000, 0.07 * 100.) == 70);
  CHECK(kept_count_from_percentage(3, 50.) == 2);
  CHECK(kept_count_from_percentage(457124, 20.) == 91425);
  CHECK_THROWS_AS(kept_count_from_percentage(10, 0.), std::invalid_argument);
  CHECK_THROWS_AS(kept_count_from_percentage(10, 100.5), std::invalid_argument);
  CHECK_THROWS_AS(kept_count_from_percentage(10, std::nan("")), std::invalid_argument);
  // a product within 1e-9 of 0 keeps one point, not none
  CHECK(kept_count_from_percentage(200, 1e-13) == 1);
  CHECK(kept_count_from_percentage(100000, 4.9e-324) == 1);
  CHECK(kept_count_from_percentage(0, 50.) == 0);
}

TEST_CASE("A tiny percentage keeps one point in the default mode, and is an error in the paper's", "[guarantees]")
{
  const std::vector<Point> points = test_clouds::wavy_surface(300, 0.005, 3).points;
  std::vector<Point> copy = points;
  const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    copy, 10, CGAL::parameters::select_percentage(1e-13));
  CHECK(std::distance(copy.begin(), first_removed) == 1);
  copy = points;
  CHECK_THROWS_WITH(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
                      copy, 10, CGAL::parameters::select_percentage(1e-13), paper_mode()),
                    Catch::Contains("must keep at least k + 1 = 11 points") && Catch::Contains("1 were asked"));
  CHECK(copy == points);
}

TEST_CASE("The removed points come last removed first: every prefix is a simplification", "[guarantees]")
{
  const std::vector<Point> points = test_clouds::wavy_surface(1500, 0.005, 7).points;
  const Run deep = paper_simplify(points, 10, CGAL::parameters::number_of_output_points(40));
  for (std::size_t m : { std::size_t(40), std::size_t(41), std::size_t(300), std::size_t(1499) })
  {
    const Run direct = paper_simplify(points, 10, CGAL::parameters::number_of_output_points(m));
    std::set<std::size_t> prefix;
    for (std::size_t j = 0; j < m; ++j)
      prefix.insert(deep.order[j]);
    INFO("m = " << m);
    CHECK(prefix == kept_positions(direct));
  }
}

TEST_CASE("A callback sees progress, and stopping leaves a valid partition", "[guarantees]")
{
  const std::vector<Point> points = test_clouds::small_replica(1600, 400, 0.002, 9).points;
  SECTION("progress is monotone and ends at 1")
  {
    std::vector<double> seen;
    const std::function<bool(double)> record = [&](double f) {
      seen.push_back(f);
      return true;
    };
    paper_simplify(points, 10, CGAL::parameters::number_of_output_points(100).callback(record));
    REQUIRE(!seen.empty());
    CHECK(std::is_sorted(seen.begin(), seen.end()));
    CHECK(seen.front() >= 0.);
    CHECK(seen.back() == Approx(1.));
  }
  SECTION("stopping during the removals keeps what was present then")
  {
    const std::function<bool(double)> stop_at_half = [](double f) { return f < 0.6; };
    const Run stopped =
      paper_simplify(points, 10, CGAL::parameters::number_of_output_points(100).callback(stop_at_half));
    CHECK(is_permutation_of_input(stopped, points));
    CHECK(stopped.kept > 100);
    CHECK(stopped.kept < points.size());
    // What was kept is exactly what a run to that target keeps.
    const Run direct = paper_simplify(points, 10, CGAL::parameters::number_of_output_points(stopped.kept));
    CHECK(kept_positions(stopped) == kept_positions(direct));
  }
  SECTION("stopping during the initial estimation keeps everything")
  {
    const std::function<bool(double)> stop_now = [](double) { return false; };
    const Run stopped = paper_simplify(points, 10, CGAL::parameters::number_of_output_points(100).callback(stop_now));
    CHECK(stopped.kept == points.size());
    CHECK(is_permutation_of_input(stopped, points));
  }
}

TEST_CASE("Results are deterministic, and the same sequentially and in parallel", "[guarantees]")
{
  test_parallel::require_tbb();
  const std::vector<Point> points = test_clouds::small_replica(40000, 9000, 0.002, 13).points;
  const auto np = CGAL::parameters::select_percentage(10.);
  const Run first = paper_simplify<CGAL::Sequential_tag>(points, 10, np);
  const Run again = paper_simplify<CGAL::Sequential_tag>(points, 10, np);
  const Run parallel =
    test_parallel::on_two_threads_or_more([&] { return paper_simplify<test_parallel::Parallel_tag>(points, 10, np); });
  CHECK(first.order == again.order);
  CHECK(first.order == parallel.order);
}

TEST_CASE("Bad input gets a documented behaviour", "[bad input]")
{
  const std::vector<Point> points = test_clouds::wavy_surface(300, 0.01, 17).points;
  const auto count = [](std::size_t n) { return CGAL::parameters::number_of_output_points(n); };

  SECTION("an empty range returns end()")
  {
    std::vector<Point> empty;
    CHECK(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(empty, 10, count(5)) == empty.end());
  }
  SECTION("fewer than k + 1 points, or k out of range, is an error")
  {
    std::vector<Point> few(points.begin(), points.begin() + 10);
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(few, 10, count(5), paper_mode()),
                    std::invalid_argument);
    std::vector<Point> copy = points;
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 1, count(50), paper_mode()),
                    std::invalid_argument);
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 1001, count(50), paper_mode()),
                    std::invalid_argument);
    ES::Options jet = paper_mode();
    jet.normal_estimation = ES::Normal_estimation::jet;
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 4, count(50), jet),
                    std::invalid_argument);
    CHECK(copy == points);
  }
  SECTION("a target of 0, or below k + 1, is an error; a target above the size keeps everything")
  {
    std::vector<Point> copy = points;
    const ES::Options paper = paper_mode();
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(0), paper),
                    std::invalid_argument);
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(10), paper),
                    std::invalid_argument);
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
                      copy, 10, CGAL::parameters::number_of_output_points(-3), paper),
                    std::invalid_argument);
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
                      copy, 10, CGAL::parameters::select_percentage(0.), paper),
                    std::invalid_argument);
    CHECK(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(points.size()), paper) ==
          copy.end());
    CHECK(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(10 * points.size()), paper) ==
          copy.end());
    CHECK(copy == points);
  }
  SECTION("NaN or infinite coordinates are rejected before anything moves")
  {
    for (double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
    {
      std::vector<Point> copy = points;
      copy[42] = Point(0.5, bad, 0.);
      const std::vector<Point> before = copy;
      CHECK_THROWS_WITH(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(50)),
                        Catch::Contains("point #42"));
      // bitwise, since NaN != NaN
      CHECK(std::memcmp(copy.data(), before.data(), copy.size() * sizeof(Point)) == 0);
    }
  }
  SECTION("coordinates beyond 1e150 are rejected before anything moves, in both modes; up to it they work")
  {
    for (const ES::Options& options : { ES::Options(), paper_mode() })
    {
      for (double huge : { 1e155, -2e150, 1e300 })
      {
        std::vector<Point> copy = points;
        copy[7] = Point(0.5, 0.5, huge);
        const std::vector<Point> before = copy;
        CHECK_THROWS_WITH(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(50), options),
                          Catch::Contains("point #7") && Catch::Contains("1e150"));
        CHECK(copy == before);
      }
      // the whole cloud at the limit's scale: a valid simplification, not a crash
      std::vector<Point> scaled;
      for (const Point& p : points)
        scaled.push_back(Point(p.x() * 1e149, p.y() * 1e149, p.z() * 1e149));
      const std::vector<Point> before = scaled;
      const auto first_removed =
        CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(scaled, 10, count(50), options);
      CHECK(std::distance(scaled.begin(), first_removed) == 50);
      CHECK(std::is_permutation(scaled.begin(), scaled.end(), before.begin()));
    }
  }
  SECTION("a cloud spanning less than 1e-150 is rejected before anything moves, in both modes; at 1e-140 it works")
  {
    for (const ES::Options& options : { ES::Options(), paper_mode() })
    {
      for (double scale : { 1e-140, 1e-160, 1e-200, 1e-300 })
      {
        std::vector<Point> scaled;
        for (const Point& p : points)
          scaled.push_back(Point(p.x() * scale, p.y() * scale, p.z() * scale));
        const std::vector<Point> before = scaled;
        if (scale > 1e-150)
        {
          const auto first_removed =
            CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(scaled, 10, count(50), options);
          CHECK(std::distance(scaled.begin(), first_removed) == 50);
          CHECK(std::is_permutation(scaled.begin(), scaled.end(), before.begin()));
        }
        else
        {
          CHECK_THROWS_WITH(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(scaled, 10, count(50), options),
                            Catch::Contains("which is not 0 but below 1e-150"));
          CHECK(scaled == before);
        }
      }
    }
  }
  SECTION("distinct points too near to be told apart, in a cloud of ordinary extent, are rejected before anything "
          "moves, by every function that orders neighbours, in both modes; coincident copies are not")
  {
    // a cluster of 3,000 points 1e-200 wide: their squared distances
    // underflow to 0, and a search among them used to visit them all, a
    // run taking minutes
    std::vector<Point> cluster = points;
    for (int i = 0; i < 3000; ++i)
      cluster.push_back(Point(1e-200 * (i % 17), 1e-200 * (i / 17), 1e-200 * (i % 5)));
    // one pair 1e-160 apart: its squared distance is subnormal
    std::vector<Point> pair = points;
    pair.push_back(Point(1e-160, 0., 0.));
    pair.push_back(Point(2e-160, 0., 0.));
    const std::string message = "closer than about 1.5e-154";
    for (const std::vector<Point>& input : { cluster, pair })
    {
      for (const ES::Options& options : { ES::Options(), paper_mode() })
      {
        std::vector<Point> copy = input;
        CHECK_THROWS_WITH(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(50), options),
                          Catch::Contains(message));
        CHECK(copy == input);
        std::vector<std::size_t> ranks;
        CHECK_THROWS_WITH(CGAL::entropy_simplification_ranks<CGAL::Sequential_tag>(
                            copy, 10, std::back_inserter(ranks), CGAL::parameters::default_values(), options),
                          Catch::Contains(message));
        CHECK(ranks.empty());
      }
      std::vector<std::pair<Point, double> > with_importance;
      for (const Point& p : input)
        with_importance.emplace_back(p, 0.);
      CHECK_THROWS_WITH(CGAL::compute_entropy_importance<CGAL::Sequential_tag>(
                          with_importance, 10, CGAL::Second_of_pair_property_map<std::pair<Point, double> >(),
                          CGAL::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<Point, double> >())),
                        Catch::Contains(message));
      CHECK_THROWS_WITH(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(input, 10),
                        Catch::Contains(message));
    }
    // 1e-150 apart, the squared distance is a normal double: told apart
    std::vector<Point> apart = points;
    apart.push_back(Point(1e-150, 0., 0.));
    apart.push_back(Point(2e-150, 0., 0.));
    for (const ES::Options& options : { ES::Options(), paper_mode() })
    {
      std::vector<Point> copy = apart;
      CHECK(std::distance(copy.begin(),
                          CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(50), options)) == 50);
    }
    // copies of a point coincide: they are no such pair, in either function
    // that takes them (collapsed by the simplification, kept by the entropy)
    std::vector<Point> copies = points;
    copies.insert(copies.end(), 30, points[7]);
    CHECK(std::isfinite(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(copies, 10)));
    CHECK(std::distance(copies.begin(), CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
                                          copies, 10, count(50), paper_mode())) == 50);
  }
  SECTION("a null reference normal is an error")
  {
    std::vector<Point> copy = points;
    ES::Options options = paper_mode();
    options.reference_normal = std::array<double, 3>{ 0., 0., 0. };
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(50), options),
                    std::invalid_argument);
  }
  SECTION("duplicated points: identical to the brute force (see above); fewer than k + 1 distinct points is an error")
  {
    std::vector<Point> same(40, Point(1., 2., 3.));
    const std::vector<Point> before = same;
    CHECK_THROWS_WITH(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(same, 5, count(12), paper_mode()),
                      Catch::Contains("k + 1 distinct points") && Catch::Contains("has 1 (of 40 points)"));
    CHECK(same == before);
  }
  SECTION("a planar cloud: equal importances, removed in input order")
  {
    std::vector<Point> plane;
    for (const Point& p : points)
      plane.emplace_back(p.x(), p.y(), 0.);
    const Run run = paper_simplify(plane, 10, count(100));
    std::set<std::size_t> last;
    for (std::size_t i = plane.size() - 100; i < plane.size(); ++i)
      last.insert(i);
    CHECK(kept_positions(run) == last);
  }
  SECTION("a collinear cloud gives a deterministic, exact-count result")
  {
    std::vector<Point> line;
    for (std::size_t i = 0; i < 200; ++i)
      line.emplace_back(0.1 * double(i * 7 % 200), 0.2 * double(i * 7 % 200), -0.3 * double(i * 7 % 200));
    const Run once = paper_simplify(line, 10, count(30));
    const Run twice = paper_simplify(line, 10, count(30));
    CHECK(once.kept == 30);
    CHECK(once.order == twice.order);
    CHECK(is_permutation_of_input(once, line));
  }
}

TEST_CASE("The accuracy indicator (Eq. 6-7)", "[indicator]")
{
  const unsigned int k = 10;
  const std::vector<Point> points = test_clouds::wavy_surface(1000, 0.005, 21).points;
  SECTION("it is the mean of the brute-force importances, in bits")
  {
    const ES::Options options;
    const auto state = brute_force::compute_state(points, std::vector<bool>(points.size(), true), k, options,
                                                  ES::internal::reference_normal(options, points));
    double sum = 0.;
    for (double h : state.importance)
      sum += h;
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(points, k) ==
          Approx(sum / double(points.size()) / std::log(2.)).epsilon(1e-12));
  }
  SECTION("copies count in the mean: the brute-force importances, and many copies repeat the first's")
  {
    // groups on either side of k + 1 copies, so that a point's neighbours
    // are some, all or none of its copies
    std::vector<Point> copies = points;
    std::size_t group = 0;
    for (std::size_t extra : { 1, 9, 10, 11, 12, 40, 600 })
    {
      copies.insert(copies.begin() + std::ptrdiff_t(50 * group), extra, points[90 * group + 3]);
      ++group;
    }
    // given, as the plane fitted to the points depends on their copies
    ES::Options options;
    options.reference_normal = std::array<double, 3>{ 0.1, -0.2, 1. };
    const auto mean_of = [&](const std::vector<Point>& cloud, std::size_t more_copies_of_last) {
      const auto state = brute_force::compute_state(cloud, std::vector<bool>(cloud.size(), true), k, options,
                                                    ES::internal::reference_normal(options, cloud));
      double sum = 0.;
      for (double h : state.importance)
        sum += h;
      sum += double(more_copies_of_last) * state.importance.back();
      return sum / double(cloud.size() + more_copies_of_last) / std::log(2.);
    };
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(
            copies, k, CGAL::parameters::default_values(), options) == Approx(mean_of(copies, 0)).epsilon(1e-12));

    // 200,000 copies of a point (each visited the others in each search, for
    // minutes): beyond the first k + 1, each has the importance of the
    // others, as the brute force computes it on k + 2 of them
    std::vector<Point> few_copies = points;
    few_copies.insert(few_copies.end(), k + 1, points[3]);
    std::vector<Point> many_copies = points;
    many_copies.insert(many_copies.end(), 200000, points[3]);
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(
            many_copies, k, CGAL::parameters::default_values(), options) ==
          Approx(mean_of(few_copies, 200000 - (k + 1))).epsilon(1e-9)); // 200,000 sums against one product
  }
  SECTION("a planar cloud reaches the maximum log2(k + 1)")
  {
    std::vector<Point> plane;
    for (const Point& p : points)
      plane.emplace_back(p.x(), p.y(), 0.);
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(plane, k) ==
          Approx(std::log2(double(k + 1))).epsilon(1e-12));
  }
  SECTION("the reference plane can be given")
  {
    ES::Options tilted;
    tilted.reference_normal = std::array<double, 3>{ 1., 0., 1. };
    const double fitted = CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(points, k);
    const double given = CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(
      points, k, CGAL::parameters::default_values(), tilted);
    CHECK(fitted != given);
    CHECK(given <= std::log2(double(k + 1)) + 1e-12);
  }
  SECTION("bad input")
  {
    const std::vector<Point> few(points.begin(), points.begin() + 5);
    CHECK_THROWS_AS(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(few, k), std::invalid_argument);
  }
}
