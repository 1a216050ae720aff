// Unit tests of the pieces of the default mode's feature field
// (internal/Feature_field.h) and of its stages, on values worked out by hand
// in the comments, and of the normals the default mode writes.

#include <catch2/catch.hpp>

#include "test_clouds.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/internal/Feature_field.h>
#include <CGAL/Entropy_simplification/internal/Weighted_elimination.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
namespace ESI = CGAL::Entropy_simplification::internal;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;

namespace {

double tensor_entropy(const std::vector<Vector>& normals)
{
  return ESI::normal_tensor_entropy(normals.size(), [&](std::size_t i) -> const Vector& { return normals[i]; });
}

Approx near(double value) { return Approx(value).epsilon(1e-12).margin(1e-12); }

} // namespace

TEST_CASE("Feature field: the entropy of the orientation tensor of normals", "[feature field]")
{
  SECTION("one direction, whatever the signs and lengths: 0")
  {
    // every u u^T is e e^T: the tensor e e^T has the eigenvalues 0, 0, 1, and
    // -1 log 1 = 0. The closed-form eigen solver finds a double eigenvalue 0
    // only to about 1e-9, whose -mu log mu is about 1e-7: far below the
    // one-degree floor, 0.0027.
    CHECK(tensor_entropy({ Vector(0, 0, 1), Vector(0, 0, -1), Vector(0, 0, 2), Vector(0, 0, -0.5) }) ==
          Approx(0.).margin(1e-6));
    CHECK(tensor_entropy({ Vector(1, 2, 2), Vector(-2, -4, -4), Vector(0.5, 1, 1) }) == Approx(0.).margin(1e-6));
  }
  SECTION("two orthogonal directions in equal numbers: log 2")
  {
    // (1, 1, 0) and (1, -1, 0), twice each, in any sign: eigenvalues 1/2, 1/2
    // and 0, so -2 (1/2) log(1/2) = log 2
    CHECK(tensor_entropy({ Vector(1, 1, 0), Vector(-2, -2, 0), Vector(1, -1, 0), Vector(-1, 1, 0) }) ==
          near(std::log(2.)));
  }
  SECTION("three mutually orthogonal directions in equal numbers: log 3")
  {
    // eigenvalues 1/3 each: -3 (1/3) log(1/3) = log 3
    CHECK(tensor_entropy({ Vector(1, 0, 0), Vector(0, -1, 0), Vector(0, 0, 1), Vector(2, 0, 0), Vector(0, 3, 0),
                           Vector(0, 0, -4) }) == near(std::log(3.)));
  }
  SECTION("two directions in unequal numbers")
  {
    // three x, one y: eigenvalues 3/4 and 1/4, so
    // -(3/4) log(3/4) - (1/4) log(1/4) = log 4 - (3/4) log 3
    //   = 1.3862943611 - 0.75 * 1.0986122887 = 1.3862943611 - 0.8239592165 = 0.5623351446
    CHECK(tensor_entropy({ Vector(1, 0, 0), Vector(1, 0, 0), Vector(-1, 0, 0), Vector(0, 1, 0) }) ==
          Approx(0.5623351446).epsilon(1e-9));
  }
  SECTION("null normals are left out")
  {
    // x, y and a null normal: eigenvalues 1/2, 1/2, so log 2; counting the
    // null normal in 1/m would give 1/3, 1/3 and (2/3) log 3 = 0.7324
    CHECK(tensor_entropy({ Vector(1, 0, 0), CGAL::NULL_VECTOR, Vector(0, 1, 0) }) == near(std::log(2.)));
    CHECK(tensor_entropy({ CGAL::NULL_VECTOR, CGAL::NULL_VECTOR }) == 0.);
  }
}

TEST_CASE("Feature field: the median and the noise floor", "[feature field]")
{
  SECTION("the median: the middle value, the upper of the two middle ones for an even count")
  {
    CHECK(ESI::median({ 0.9, 0.1, 0.2 }) == 0.2);
    CHECK(ESI::median({ 5. }) == 5.);
    // sorted 0.1 0.2 0.3 0.4: the value at 4 / 2 = 2
    CHECK(ESI::median({ 0.4, 0.1, 0.3, 0.2 }) == 0.3);
  }
  SECTION("the floor is the median entropy")
  {
    // median 0.2; the mean would be (0.9 + 0.1 + 0.2) / 3 = 0.4
    CHECK(ESI::entropy_noise_floor({ 0.9, 0.1, 0.2 }) == 0.2);
    // median 0.3; the mean would be 0.325
    CHECK(ESI::entropy_noise_floor({ 0.3, 0.3, 0.7, 0.0, 0.3 }) == 0.3);
  }
  SECTION("the floor is at least the entropy of a one-degree spread")
  {
    // a = 0.0175 rad, two eigenvalues a^2 / 2 = 0.000153125:
    // log(0.000153125) = log(49 / 32) + log(1e-4) = (2 log 7 - 5 log 2) - 4 log 10
    //   = (3.8918202981 - 3.4657359028) - 9.2103403720 = -8.7842559767
    // floor = -2 * 0.000153125 * -8.7842559767 = 0.00030625 * 8.7842559767 = 0.0026901784
    const double one_degree = 0.0026901784;
    // median 0; the mean would be 0.34
    CHECK(ESI::entropy_noise_floor({ 0.9, 0., 0.8, 0., 0. }) == Approx(one_degree).epsilon(1e-8));
    CHECK(ESI::entropy_noise_floor({ 0.002, 0.001, 0.5 }) == Approx(one_degree).epsilon(1e-8));
    CHECK(ESI::entropy_noise_floor({}) == Approx(one_degree).epsilon(1e-8));
    // just above it, the median again
    CHECK(ESI::entropy_noise_floor({ 0.003, 0.003, 0.001 }) == 0.003);
  }
}

TEST_CASE("Feature field: the strength rises linearly from twice to ten times the floor", "[feature field]")
{
  const double floor = 0.1;
  CHECK(ESI::feature_strength(0., floor) == 0.);
  CHECK(ESI::feature_strength(0.15, floor) == 0.);
  CHECK(ESI::feature_strength(0.2, floor) == near(0.));
  // (0.4 - 0.2) / 0.8 = 0.25, (0.6 - 0.2) / 0.8 = 0.5
  CHECK(ESI::feature_strength(0.4, floor) == near(0.25));
  CHECK(ESI::feature_strength(0.6, floor) == near(0.5));
  CHECK(ESI::feature_strength(1.0, floor) == near(1.));
  CHECK(ESI::feature_strength(2.0, floor) == 1.);
  // six times any floor: (6 - 2) / 8 = 0.5
  CHECK(ESI::feature_strength(6. * 0.0026901784, 0.0026901784) == near(0.5));
}

TEST_CASE("Feature field: the feature budget", "[feature field]")
{
  // a weight of 3 on 30% of the area adds 0.9 of the area in points, more
  // than the budget of 0.45: the weight becomes 0.45 / 0.3 = 1.5
  CHECK(ESI::budgeted_feature_weight(3., 0.3, 1.) == near(1.5));
  CHECK(ESI::budgeted_feature_weight(3., 0.3, 1.) * 0.3 == near(0.45));
  // the budget follows the weight: 0.45 * 2 / 3 = 0.3 at a weight of 2, and
  // 0.3 * 10 / 30 = 0.1; 0.9 at a weight of 6, and 0.9 / 0.3 = 3, twice the
  // weight that 3 becomes on the same area
  CHECK(ESI::budgeted_feature_weight(2., 30., 10.) == near(0.1));
  CHECK(ESI::budgeted_feature_weight(6., 0.3, 1.) == near(3.));
  // so the weight scales by the same factor, 15% over the marked fraction of the area
  for (double w : { 0.5, 1., 3., 4.5, 10. })
    CHECK(ESI::budgeted_feature_weight(w, 0.6, 1.) == near(w * 0.15 / 0.6));
  // within the budget (3 * 0.1 = 0.3 <= 0.45, 6 * 0.1 <= 0.9), or without
  // features, the weight stays
  CHECK(ESI::budgeted_feature_weight(3., 0.1, 1.) == 3.);
  CHECK(ESI::budgeted_feature_weight(6., 0.1, 1.) == 6.);
  CHECK(ESI::budgeted_feature_weight(3., 0., 1.) == 3.);
  CHECK(ESI::budgeted_feature_weight(0., 0.5, 1.) == 0.);
}

TEST_CASE("Feature field: the interaction and density scales", "[feature field]")
{
  SECTION("the interaction scale: 1 / sqrt(1 + w s), so the density grows by 1 + w s")
  {
    CHECK(ESI::interaction_scale(0., 3.) == 1.);
    CHECK(ESI::interaction_scale(1., 0.) == 1.);
    // 1 / sqrt(1 + 3) = 1 / 2, the density 4 times that of flat regions
    CHECK(ESI::interaction_scale(1., 3.) == near(0.5));
    CHECK(ESI::interaction_scale(0.5, 6.) == near(0.5));
    // 1 / sqrt(1 + 8) = 1 / 3
    CHECK(ESI::interaction_scale(1., 8.) == near(1. / 3.));
  }
  SECTION("the density scale: the cube root of the area over the typical area, within [0.5, 2]")
  {
    // 1.5^3 = 3.375, 0.8^3 = 0.512, 2^3 = 8
    CHECK(ESI::density_scale(3.375, 1.) == near(1.5));
    CHECK(ESI::density_scale(6.75, 2.) == near(1.5));
    CHECK(ESI::density_scale(0.512, 1.) == near(0.8));
    CHECK(ESI::density_scale(8., 1.) == near(2.));
    // cube roots 3 and 1/3, clamped
    CHECK(ESI::density_scale(27., 1.) == 2.);
    CHECK(ESI::density_scale(1. / 27., 1.) == 0.5);
    CHECK(ESI::density_scale(0., 1.) == 0.5);
    // no typical area (all points coincide): no density term
    CHECK(ESI::density_scale(1., 0.) == 1.);
  }
}

TEST_CASE("Feature field: the scales are rounded to 30 significant bits", "[feature field]")
{
  // 30 bits of significand, the leading one included: 2^-29 apart in [1, 2),
  // 2^-30 apart in [0.5, 1); halves round away from zero
  const double step = std::ldexp(1., -29);
  CHECK(ESI::with_30_bit_significand(1.) == 1.);
  CHECK(ESI::with_30_bit_significand(1. + step / 4) == 1.);
  CHECK(ESI::with_30_bit_significand(1. + step / 2) == 1. + step);
  CHECK(ESI::with_30_bit_significand(1. + 3 * step / 4) == 1. + step);
  CHECK(ESI::with_30_bit_significand(2. - step / 4) == 2.);
  CHECK(ESI::with_30_bit_significand(0.75 + step / 8) == 0.75);
  CHECK(ESI::with_30_bit_significand(0.75 + 3 * step / 8) == 0.75 + step / 2);
  CHECK(ESI::with_30_bit_significand(0.) == 0.);
  // a value of 30 significant bits stays: 2^29 + 1 scaled
  const double thirty_bits = (std::ldexp(1., 29) + 1.) / 1024.;
  CHECK(ESI::with_30_bit_significand(thirty_bits) == thirty_bits);
  // 1/3 = 0.0101...b: the nearest multiple of 2^-31 in [0.25, 0.5)
  const double third = std::round(std::ldexp(1. / 3., 31)) / std::ldexp(1., 31);
  CHECK(ESI::with_30_bit_significand(1. / 3.) == third);
  CHECK(std::abs(third - 1. / 3.) <= std::ldexp(1., -32));
}

TEST_CASE("Feature field: the coarse stride and the stages of the elimination", "[feature field]")
{
  // the manual's every 64th point: a spacing sqrt(64) = 8 times wider
  CHECK(ESI::coarse_stride == 64);

  SECTION("a stage halves the count, the last one reaches the target")
  {
    // an area of 1000 sqrt(3): the hexagons of 500 points of radius r cover
    // 500 * 2 sqrt(3) r^2 = 1000 sqrt(3), so r = 1; the limit is
    // 0.65 r (1 - (500 / 1000)^1.5) = 0.65 (1 - 0.3535533906) = 0.4201902961
    const double area = 1000. * std::sqrt(3.);
    const ESI::Elimination_stage first = ESI::next_stage(1000, 100, area);
    CHECK(first.target == 500);
    CHECK(first.radius == near(1.));
    CHECK(first.limit == Approx(0.4201902961).epsilon(1e-9));
    // (7 + 1) / 2 = 4
    CHECK(ESI::next_stage(7, 2, area).target == 4);
    // 150 points to 100: 100 points, r = sqrt(1000 / (2 * 100)) = sqrt(5) = 2.2360679775,
    // (100 / 150)^1.5 = (2/3) sqrt(2/3) = 0.6666666667 * 0.8164965809 = 0.5443310540,
    // limit = 2.2360679775 * 0.65 * (1 - 0.5443310540) = 2.2360679775 * 0.2961848149 = 0.6622893801
    const ESI::Elimination_stage last = ESI::next_stage(150, 100, area);
    CHECK(last.target == 100);
    CHECK(last.radius == Approx(2.2360679775).epsilon(1e-10));
    CHECK(last.limit == Approx(0.6622893801).epsilon(1e-9));
  }
  SECTION("the weight of a pair: (1 - d / 2 r s)^2 in units of 2^-40")
  {
    const ESI::Elimination_stage stage{ 100, 1., 0.4 };
    const Point a(0, 0, 0);
    // reach 2: d = 1 gives (1/2)^2 = 2^-2, that is 2^38 units
    CHECK(ESI::pair_weight(a, Point(1, 0, 0), 1., 1., stage) == 274877906944);
    // d = 0.3 counts as the limit 0.4: (1 - 0.2)^2 = 0.64, times 2^40 =
    // 703687441776.64
    CHECK(ESI::pair_weight(a, Point(0.3, 0, 0), 1., 1., stage) == 703687441777);
    // at and beyond the reach: nothing
    CHECK(ESI::pair_weight(a, Point(2, 0, 0), 1., 1., stage) == 0);
    CHECK(ESI::pair_weight(a, Point(0, 3, 4), 1., 1., stage) == 0);
    // scales 1 and 0.5: s = 0.75, reach 1.5, d = 0.75 gives (1/2)^2 again, either way round
    CHECK(ESI::pair_weight(a, Point(0, 0.75, 0), 1., 0.5, stage) == 274877906944);
    CHECK(ESI::pair_weight(Point(0, 0.75, 0), a, 0.5, 1., stage) == 274877906944);
  }
  SECTION("the eighth power in the stages that keep more than 55% of the input")
  {
    CHECK(ESI::keeps_most_points(56, 100));
    CHECK_FALSE(ESI::keeps_most_points(55, 100));
    CHECK_FALSE(ESI::keeps_most_points(50, 100));
    // 11 of 20 is exactly 55%
    CHECK_FALSE(ESI::keeps_most_points(11, 20));
    CHECK(ESI::keeps_most_points(12, 20));
    ESI::Elimination_stage stage{ 100, 1., 0.4 };
    stage.eighth_power = true;
    // d = 1 within reach 2: (1/2)^8 = 2^-8, that is 2^32 units
    CHECK(ESI::pair_weight(Point(0, 0, 0), Point(1, 0, 0), 1., 1., stage) == 4294967296);
    // d = 0.3 counts as the limit 0.4: 0.8^8 = 0.16777216, times 2^40 =
    // 184467440737.09551616
    CHECK(ESI::pair_weight(Point(0, 0, 0), Point(0.3, 0, 0), 1., 1., stage) == 184467440737);
    CHECK(ESI::pair_weight(Point(0, 0, 0), Point(2, 0, 0), 1., 1., stage) == 0);
  }
}

TEST_CASE("Default mode: the normals written are CGAL's normals of the input at the kept points",
          "[default][feature field]")
{
  using Element = std::tuple<Point, Vector, std::size_t>; // point, written normal, input position
  using Point_of = CGAL::Nth_of_tuple_property_map<0, Element>;
  using Normal_of = CGAL::Nth_of_tuple_property_map<1, Element>;
  using Pair_point_of = CGAL::First_of_pair_property_map<std::pair<Point, Vector> >;
  using Pair_normal_of = CGAL::Second_of_pair_property_map<std::pair<Point, Vector> >;
  const unsigned int k = 10;
  for (const test_clouds::Cloud& cloud :
       { test_clouds::wavy_surface(2000, 0.01, 5), test_clouds::small_replica(1600, 400, 0.002, 6) })
    for (ES::Normal_estimation method : { ES::Normal_estimation::pca, ES::Normal_estimation::jet })
    {
      INFO(cloud.name << ", normals " << int(method));
      // CGAL's normal of each input point, from it and its k nearest neighbours
      std::vector<std::pair<Point, Vector> > input;
      for (const Point& p : cloud.points)
        input.emplace_back(p, CGAL::NULL_VECTOR);
      const auto input_maps = CGAL::parameters::point_map(Pair_point_of()).normal_map(Pair_normal_of());
      if (method == ES::Normal_estimation::jet)
        CGAL::jet_estimate_normals<CGAL::Sequential_tag>(input, k, input_maps);
      else
        CGAL::pca_estimate_normals<CGAL::Sequential_tag>(input, k, input_maps);

      std::vector<Element> range;
      for (std::size_t i = 0; i < cloud.points.size(); ++i)
        range.emplace_back(cloud.points[i], CGAL::NULL_VECTOR, i);
      ES::Options options;
      options.normal_estimation = method;
      const auto kept_end = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
        range, k, CGAL::parameters::number_of_output_points(200).point_map(Point_of()).normal_map(Normal_of()),
        options);
      REQUIRE(kept_end - range.begin() == 200);

      // normals up to orientation, which neither defines
      double largest_difference = 0.;
      for (auto it = range.begin(); it != kept_end; ++it)
      {
        const Vector& written = std::get<1>(*it);
        const Vector& expected = input[std::get<2>(*it)].second;
        const double difference =
          std::sqrt((std::min)((written - expected).squared_length(), (written + expected).squared_length()));
        largest_difference = (std::max)(largest_difference, difference);
      }
      CHECK(largest_difference <= 1e-9);
    }
}

// The coarse scale takes seconds with a large k (about 2.5 s for 300,000
// points at k = 1000), so it reports its progress and honours a stop.
TEST_CASE("Feature field: the coarse scale reports its progress and stops when asked", "[feature field]")
{
  const test_clouds::Cloud cloud = test_clouds::wavy_surface(40000, 0.002, 17);
  const ESI::Indexed_points points =
    ESI::sort_spatially(ESI::Array<ESI::Working_point>(cloud.points.begin(), cloud.points.end()));
  const unsigned int k = 10;
  ESI::Array<ESI::Index> knn;
  ESI::Array<double> entropy;
  auto go_on = [](double) { return true; };
  REQUIRE(ESI::nearest_neighbors_of_all<CGAL::Sequential_tag>(points, k, knn, go_on));
  REQUIRE(ESI::normal_entropy_of_all<CGAL::Sequential_tag>(points, k, ES::Normal_estimation::pca, knn, entropy,
                                                             go_on));

  std::vector<double> fractions;
  ESI::Array<double> strength;
  REQUIRE(ESI::feature_strengths<CGAL::Sequential_tag>(points, k, ES::Normal_estimation::pca, entropy, true, strength,
                                                         [&](double f) {
                                                           fractions.push_back(f);
                                                           return true;
                                                         }));
  REQUIRE(strength.size() == points.size());
  CHECK(std::count_if(strength.begin(), strength.end(), [](double s) { return s > 0.; }) > 0);
  // each of the three passes reports at least at its end, in order, up to 1
  REQUIRE(fractions.size() >= 3);
  CHECK(std::is_sorted(fractions.begin(), fractions.end()));
  CHECK(fractions.front() > 0.);
  CHECK(fractions.back() == 1.);
  for (double third : { 1. / 3., 2. / 3. })
    CHECK(std::find_if(fractions.begin(), fractions.end(), [&](double f) { return std::abs(f - third) < 1e-12; }) !=
          fractions.end());

  // asked to stop at its first report, or at the first of its last pass, it
  // stops there
  for (double stop_from : { 0., 2. / 3. + 1e-9 })
  {
    std::size_t calls = 0, calls_after_stop = 0;
    bool stopped = false;
    ESI::Array<double> partial;
    const bool completed = ESI::feature_strengths<CGAL::Sequential_tag>(
      points, k, ES::Normal_estimation::pca, entropy, true, partial, [&](double f) {
        ++calls;
        calls_after_stop += stopped;
        stopped = stopped || f >= stop_from;
        return !stopped;
      });
    CHECK_FALSE(completed);
    CHECK(stopped);
    CHECK(calls_after_stop == 0);
    CHECK(calls < fractions.size());
  }
}
