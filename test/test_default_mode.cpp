// Tests of the default mode (Mode::weighted_elimination): the removal order
// against a brute-force reference, the guarantees of entropy_simplify_point_set
// in that mode (count, subset, permutation, callback, determinism, bad input),
// and what the mode is for: no holes, and more points on features.

#include <catch2/catch.hpp>

#include "brute_force_elimination.h"
#include "test_clouds.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Indexed = std::pair<Point, std::size_t>;
using Point_of = CGAL::First_of_pair_property_map<Indexed>;

namespace {

// The input positions of the range after a call, and where the kept points end.
struct Run
{
  std::vector<std::size_t> order;
  std::size_t kept = 0;
};

template <typename Tag = CGAL::Sequential_tag, typename NP>
Run simplify(const std::vector<Point>& points, unsigned int k, const NP& np, const ES::Options& options = {})
{
  std::vector<Indexed> range;
  for (std::size_t i = 0; i < points.size(); ++i)
    range.emplace_back(points[i], i);
  const auto it = CGAL::entropy_simplify_point_set<Tag>(range, k, np.point_map(Point_of()), options);
  Run run;
  run.kept = std::size_t(it - range.begin());
  for (const Indexed& e : range)
  {
    REQUIRE(e.first == points[e.second]);
    run.order.push_back(e.second);
  }
  return run;
}

std::vector<std::size_t> removal_order(const Run& run)
{
  return std::vector<std::size_t>(run.order.rbegin(), run.order.rend() - std::ptrdiff_t(run.kept));
}

bool is_permutation(const Run& run, std::size_t n)
{
  std::vector<std::size_t> sorted = run.order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (sorted[i] != i)
      return false;
  return sorted.size() == n;
}

// The largest distance from an input point to its nearest kept point.
double largest_gap(const std::vector<Point>& points, const Run& run)
{
  double largest = 0.;
  for (const Point& p : points)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < run.kept; ++j)
      nearest = (std::min)(nearest, CGAL::squared_distance(p, points[run.order[j]]));
    largest = (std::max)(largest, nearest);
  }
  return std::sqrt(largest);
}

} // namespace

TEST_CASE("Default mode: the removal order equals the brute-force elimination and relocation",
          "[default][brute force]")
{
  const std::vector<test_clouds::Cloud> clouds = {
    test_clouds::small_replica(160, 40, 0.002, 1), test_clouds::wavy_surface(200, 0.01, 2),
    test_clouds::cube_volume(150, 3), test_clouds::bent_grid(14), test_clouds::with_duplicates(80, 4)
  };
  for (const test_clouds::Cloud& cloud : clouds)
    for (double feature_weight : { 0., 3. })
      for (ES::Normal_estimation method : { ES::Normal_estimation::pca, ES::Normal_estimation::jet })
        // one stage, then several stages halving the count
        for (std::size_t divisor : { std::size_t(2), std::size_t(7) })
        {
          ES::Options options;
          options.feature_weight = feature_weight;
          options.normal_estimation = method;
          const unsigned int k = 8;
          const std::size_t target = cloud.points.size() / divisor;
          INFO(cloud.name << ", feature weight " << feature_weight << ", normals " << int(method) << ", target "
                          << target);
          const std::vector<std::size_t> reference = brute_force::default_mode_sequence(
            cloud.points, k, target, options, ES::internal::relocation_iterations);
          const Run run = simplify(cloud.points, k, CGAL::parameters::number_of_output_points(target), options);
          CHECK(run.kept == target);
          CHECK(removal_order(run) == reference);
        }
}

TEST_CASE("Default mode: exact count, a subset, nothing lost, deterministic", "[default][guarantees]")
{
  const std::vector<Point> points = test_clouds::small_replica(16000, 4000, 0.002, 5).points;
  for (std::size_t target : { std::size_t(1), std::size_t(2), std::size_t(11), std::size_t(1000),
                              std::size_t(19999), std::size_t(20000), std::size_t(50000) })
  {
    INFO("target " << target);
    const Run run = simplify(points, 10, CGAL::parameters::number_of_output_points(target));
    CHECK(run.kept == (std::min)(target, points.size()));
    CHECK(is_permutation(run, points.size()));
  }
  for (double percentage : { 0.01, 7., 10., 50., 100. })
  {
    INFO("percentage " << percentage);
    const Run run = simplify(points, 10, CGAL::parameters::select_percentage(percentage));
    CHECK(run.kept == ES::internal::kept_count_from_percentage(points.size(), percentage));
    CHECK(is_permutation(run, points.size()));
  }
  const auto np = CGAL::parameters::select_percentage(10.);
  const Run first = simplify(points, 10, np);
  CHECK(simplify(points, 10, np).order == first.order);
  CHECK(simplify<CGAL::Parallel_if_available_tag>(points, 10, np).order == first.order);
}

TEST_CASE("Default mode: the callback sees progress and can stop it", "[default][guarantees]")
{
  const std::vector<Point> points = test_clouds::small_replica(4000, 1000, 0.002, 9).points;
  std::vector<double> seen;
  const std::function<bool(double)> record = [&](double f) {
    seen.push_back(f);
    return true;
  };
  simplify(points, 10, CGAL::parameters::number_of_output_points(500).callback(record));
  REQUIRE(!seen.empty());
  CHECK(std::is_sorted(seen.begin(), seen.end()));
  CHECK(seen.back() == Approx(1.));

  const std::function<bool(double)> stop_at_half = [](double f) { return f < 0.6; };
  const Run stopped = simplify(points, 10, CGAL::parameters::number_of_output_points(500).callback(stop_at_half));
  CHECK(is_permutation(stopped, points.size()));
  CHECK(stopped.kept > 500);
  CHECK(stopped.kept < points.size());
}

TEST_CASE("Default mode: flat regions thin evenly, features keep more points", "[default][quality]")
{
  // A folded sheet: two flat halves meeting at a right-angled crease x = 0.
  test_clouds::Random random(31);
  std::vector<Point> folded;
  for (std::size_t i = 0; i < 20000; ++i)
  {
    const double u = 2. * random.uniform() - 1., v = random.uniform();
    folded.emplace_back(u < 0. ? u : 0., v, u < 0. ? 0. : u);
  }
  const std::size_t target = 1000;
  // For an even sample, each kept point covers about 2 / target of the area.
  const double spacing = std::sqrt(2. / double(target));
  ES::Options paper;
  paper.mode = ES::Mode::paper;
  const Run even = simplify(folded, 10, CGAL::parameters::number_of_output_points(target));
  const Run literal = simplify(folded, 10, CGAL::parameters::number_of_output_points(target), paper);
  const double gap = largest_gap(folded, even);
  INFO("largest gap: default " << gap << ", paper " << largest_gap(folded, literal) << ", spacing " << spacing);
  CHECK(gap < 1.5 * spacing);
  CHECK(gap < largest_gap(folded, literal));

  const auto near_crease = [&](const Run& run) {
    std::size_t count = 0;
    for (std::size_t j = 0; j < run.kept; ++j)
      count += std::abs(folded[run.order[j]].x()) + std::abs(folded[run.order[j]].z()) < 0.05 ? 1 : 0;
    return count;
  };
  ES::Options without_entropy;
  without_entropy.feature_weight = 0.;
  const Run plain = simplify(folded, 10, CGAL::parameters::number_of_output_points(target), without_entropy);
  INFO("near the crease: default " << near_crease(even) << ", without the entropy term " << near_crease(plain));
  CHECK(near_crease(even) > 3 * near_crease(plain) / 2);
}

TEST_CASE("Default mode: bad input gets a documented behaviour", "[default][bad input]")
{
  const std::vector<Point> points = test_clouds::wavy_surface(300, 0.01, 17).points;
  const auto count = [](std::size_t n) { return CGAL::parameters::number_of_output_points(n); };
  SECTION("a feature weight that is negative or not finite is an error, before anything moves")
  {
    for (double bad : { -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
    {
      ES::Options options;
      options.feature_weight = bad;
      std::vector<Point> copy = points;
      CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(50), options),
                      std::invalid_argument);
      CHECK(copy == points);
    }
  }
  SECTION("a target of 0 is an error; any positive target is reached")
  {
    std::vector<Point> copy = points;
    CHECK_THROWS_AS(CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(copy, 10, count(0)), std::invalid_argument);
    CHECK(simplify(points, 10, count(1)).kept == 1);
    CHECK(simplify(points, 10, count(5)).kept == 5);
  }
  SECTION("the options of the paper's mode are ignored")
  {
    ES::Options reversed;
    reversed.removal_order = ES::Removal_order::highest_entropy_first;
    reversed.reference_normal = std::array<double, 3>{ 1., 0., 0. };
    CHECK(simplify(points, 10, count(60), reversed).order == simplify(points, 10, count(60)).order);
  }
  SECTION("all-equal points: exact count, as the brute force")
  {
    // Every interaction radius is 0: ties everywhere, broken by input position.
    const std::vector<Point> same(40, Point(1., 2., 3.));
    const Run run = simplify(same, 5, count(12));
    CHECK(run.kept == 12);
    CHECK(removal_order(run) ==
          brute_force::default_mode_sequence(same, 5, 12, ES::Options(), ES::internal::relocation_iterations));
  }
  SECTION("a collinear cloud gives a deterministic, exact-count result")
  {
    std::vector<Point> line;
    for (std::size_t i = 0; i < 200; ++i)
      line.emplace_back(0.1 * double(i * 7 % 200), 0.2 * double(i * 7 % 200), -0.3 * double(i * 7 % 200));
    const Run once = simplify(line, 10, count(30));
    CHECK(once.kept == 30);
    CHECK(once.order == simplify(line, 10, count(30)).order);
    CHECK(is_permutation(once, line.size()));
  }
}
