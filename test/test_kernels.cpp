// Every public function of the package on every kernel CGAL users use: Epick,
// Epeck, Simple_cartesian<double> and Simple_cartesian<float>. The package
// works in double precision on the coordinates of the points, so on the same
// coordinates every kernel must give exactly the result of
// Simple_cartesian<double>: the same kept points in the same order, the same
// normals (rounded to the kernel's number type) and the same indicator.

#include <catch2/catch.hpp>

#include <CGAL/Entropy_simplification/compute_mean_normal_angle_entropy.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/experiment_I_replica.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

namespace ES = CGAL::Entropy_simplification;
using Reference_kernel = CGAL::Simple_cartesian<double>;
using Coordinates = std::array<double, 3>;

constexpr unsigned int k = 10;
constexpr std::size_t board_points = 2400, sphere_points = 600;
constexpr std::size_t input_size = board_points + sphere_points;
constexpr std::size_t kept_count = 300; // also 10% of the input

template <typename PointOrVector>
Coordinates coordinates_of(const PointOrVector& p)
{
  return { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
}

// x rounded to K's number type, as a double. For float the rounding goes
// through a volatile: GCC 12.2 (Debian 12.2.0-14) at -O2 and above drops the
// rounding of a double -> float -> double round trip when its SLP vectorizer
// pairs two of them, which would make the expected values unrounded doubles.
template <typename K>
double rounded(double x)
{
  if constexpr (std::is_same<typename K::FT, float>::value)
  {
    const volatile float f = float(x);
    return double(f);
  }
  else
    return CGAL::to_double(typename K::FT(x));
}

template <typename K>
Coordinates rounded(const Coordinates& c)
{
  return { rounded<K>(c[0]), rounded<K>(c[1]), rounded<K>(c[2]) };
}

// The largest |n^2 - 1| a unit normal may show in kernel K: the package's
// double normal, rounded to K's number type.
template <typename K>
double unit_tolerance()
{
  return std::is_same<typename K::FT, float>::value ? 16. * std::numeric_limits<float>::epsilon()
                                                    : 16. * std::numeric_limits<double>::epsilon();
}

// A small replica of Experiment I, generated directly in kernel K.
template <typename K>
std::vector<std::pair<typename K::Point_3, int> > replica_in()
{
  ES::Experiment_I_setup setup;
  setup.board_points = board_points;
  setup.sphere_points = sphere_points;
  setup.seed = 29;
  std::vector<std::pair<typename K::Point_3, int> > labelled;
  ES::experiment_I_replica<typename K::Point_3>(std::back_inserter(labelled), setup);
  return labelled;
}

// The input position of each point, by coordinates (the points are distinct).
using Positions = std::map<Coordinates, std::size_t>;

std::size_t position_of(const Positions& positions, const Coordinates& c)
{
  const auto it = positions.find(c);
  return it == positions.end() ? (std::numeric_limits<std::size_t>::max)() : it->second;
}

// What a call did to a range.
struct Range_run
{
  std::size_t kept = 0;
  std::vector<std::size_t> order;   // the input position of each element, after the call
  std::vector<Coordinates> normals; // the normals written to the kept points, in range order
  bool nothing_else_written = true; // no normal written to a removed point
};

bool is_permutation_of_input(const Range_run& run)
{
  std::vector<std::size_t> sorted = run.order, identity(input_size);
  std::sort(sorted.begin(), sorted.end());
  std::iota(identity.begin(), identity.end(), std::size_t(0));
  return sorted == identity;
}

// A writable property map keyed by the point itself, for a vector of bare
// points: it records the normal of each point by its coordinates.
template <typename K>
struct Normal_by_coordinates
{
  using key_type = typename K::Point_3;
  using value_type = typename K::Vector_3;
  using reference = value_type;
  using category = boost::writable_property_map_tag;

  std::map<Coordinates, value_type>* normals;

  friend void put(const Normal_by_coordinates& map, const key_type& p, const value_type& n)
  {
    (*map.normals)[coordinates_of(p)] = n;
  }
};

// std::vector<Point_3>, number_of_output_points, a normal map keyed by point.
template <typename K>
Range_run simplify_vector(const std::vector<typename K::Point_3>& input, const ES::Options& options,
                    const Positions& positions)
{
  std::vector<typename K::Point_3> points = input;
  std::map<Coordinates, typename K::Vector_3> normals;
  const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    points, k,
    CGAL::parameters::number_of_output_points(kept_count).normal_map(Normal_by_coordinates<K>{ &normals }),
    options);
  Range_run run;
  run.kept = std::size_t(first_removed - points.begin());
  for (const auto& p : points)
    run.order.push_back(position_of(positions, coordinates_of(p)));
  for (std::size_t i = 0; i < run.kept && i < points.size(); ++i)
  {
    const auto it = normals.find(coordinates_of(points[i]));
    if (it != normals.end())
      run.normals.push_back(coordinates_of(it->second));
  }
  run.nothing_else_written = normals.size() == run.kept;
  return run;
}

// std::vector<std::pair<Point_3, Vector_3> >, select_percentage, the points
// and normals read and written through First_of_pair and Second_of_pair.
template <typename K>
Range_run simplify_pairs(const std::vector<typename K::Point_3>& input, const ES::Options& options,
                   const Positions& positions)
{
  using Pair = std::pair<typename K::Point_3, typename K::Vector_3>;
  const typename K::Vector_3 untouched(1, 2, 3);
  std::vector<Pair> pairs;
  for (const auto& p : input)
    pairs.emplace_back(p, untouched);
  const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    pairs, k,
    CGAL::parameters::select_percentage(10.)
      .point_map(CGAL::First_of_pair_property_map<Pair>())
      .normal_map(CGAL::Second_of_pair_property_map<Pair>()),
    options);
  Range_run run;
  run.kept = std::size_t(first_removed - pairs.begin());
  for (std::size_t i = 0; i < pairs.size(); ++i)
  {
    run.order.push_back(position_of(positions, coordinates_of(pairs[i].first)));
    if (i < run.kept)
      run.normals.push_back(coordinates_of(pairs[i].second));
    else
      run.nothing_else_written = run.nothing_else_written && pairs[i].second == untouched;
  }
  return run;
}

// CGAL::Point_set_3<Point_3>, with its own normal map given as normal_map.
template <typename K>
Range_run simplify_point_set(const std::vector<typename K::Point_3>& input, const ES::Options& options,
                       const Positions& positions)
{
  const typename K::Vector_3 untouched(1, 2, 3);
  CGAL::Point_set_3<typename K::Point_3> set;
  set.add_normal_map();
  for (const auto& p : input)
    set.insert(p, untouched);
  const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
    set, k, CGAL::parameters::number_of_output_points(kept_count).normal_map(set.normal_map()), options);
  Range_run run;
  run.kept = std::size_t(std::distance(set.begin(), first_removed));
  std::size_t i = 0;
  for (auto it = set.begin(); it != set.end(); ++it, ++i)
  {
    run.order.push_back(position_of(positions, coordinates_of(set.point(*it))));
    if (i < run.kept)
      run.normals.push_back(coordinates_of(set.normal(*it)));
    else
      run.nothing_else_written = run.nothing_else_written && set.normal(*it) == untouched;
  }
  return run;
}

// The reference normals, as kernel K stores them.
template <typename K>
std::vector<Coordinates> rounded_to(const std::vector<Coordinates>& normals)
{
  std::vector<Coordinates> result;
  for (const Coordinates& n : normals)
    result.push_back(rounded<K>(n));
  return result;
}

// The number of positions where two sequences differ (a size difference
// counts), which keeps failure messages short.
template <typename T>
std::size_t differences(const std::vector<T>& a, const std::vector<T>& b)
{
  std::size_t count = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  for (std::size_t i = 0; i < (std::min)(a.size(), b.size()); ++i)
    count += a[i] == b[i] ? 0 : 1;
  return count;
}

template <typename K>
bool all_unit(const std::vector<Coordinates>& normals)
{
  for (const Coordinates& n : normals)
    if (!(std::abs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.) <= unit_tolerance<K>()))
      return false;
  return true;
}

} // namespace

TEMPLATE_TEST_CASE("Every public function on every kernel gives the Simple_cartesian<double> result",
                   "[kernels]", CGAL::Epick, CGAL::Epeck, CGAL::Simple_cartesian<double>,
                   CGAL::Simple_cartesian<float>)
{
  using K = TestType;
  using Point = typename K::Point_3;

  // experiment_I_replica in this kernel: the double replica rounded to FT.
  const auto labelled = replica_in<K>();
  const auto reference_labelled = replica_in<Reference_kernel>();
  REQUIRE(labelled.size() == input_size);
  REQUIRE(reference_labelled.size() == input_size);
  bool same_replica = true;
  std::vector<Point> input;
  std::vector<Reference_kernel::Point_3> reference_input; // the same coordinates, in double
  Positions positions;
  for (std::size_t i = 0; i < input_size; ++i)
  {
    const Reference_kernel::Point_3& r = reference_labelled[i].first;
    same_replica = same_replica && labelled[i].second == reference_labelled[i].second &&
                   coordinates_of(labelled[i].first) == rounded<K>(coordinates_of(r));
    input.push_back(labelled[i].first);
    const Coordinates c = coordinates_of(labelled[i].first);
    reference_input.emplace_back(c[0], c[1], c[2]);
    positions.emplace(c, i);
  }
  CHECK(same_replica);
  REQUIRE(positions.size() == input_size); // distinct points: a position per coordinates

  for (const ES::Mode mode : { ES::Mode::weighted_elimination, ES::Mode::paper })
  {
    INFO((mode == ES::Mode::paper ? "Mode::paper" : "Mode::weighted_elimination"));
    ES::Options options;
    options.mode = mode;
    const Range_run reference = simplify_vector<Reference_kernel>(reference_input, options, positions);
    REQUIRE(reference.kept == kept_count);
    REQUIRE(is_permutation_of_input(reference));
    REQUIRE(reference.normals.size() == kept_count);
    const std::vector<Coordinates> expected_normals = rounded_to<K>(reference.normals);

    const std::pair<const char*, Range_run> runs[] = {
      { "std::vector<Point_3>", simplify_vector<K>(input, options, positions) },
      { "std::vector<std::pair<Point_3, Vector_3> >", simplify_pairs<K>(input, options, positions) },
      { "CGAL::Point_set_3<Point_3>", simplify_point_set<K>(input, options, positions) },
    };
    for (const auto& named : runs)
    {
      INFO(named.first);
      const Range_run& run = named.second;
      CHECK(run.kept == kept_count);
      CHECK(is_permutation_of_input(run));
      CHECK(differences(run.order, reference.order) == 0); // kept set and order, and the order of the removed
      CHECK(run.normals.size() == kept_count);
      CHECK(all_unit<K>(run.normals));
      CHECK(differences(run.normals, expected_normals) == 0);
      CHECK(run.nothing_else_written);
    }

    // The indicator of the simplified cloud, against the board's plane.
    std::vector<Point> kept;
    std::vector<Reference_kernel::Point_3> reference_kept;
    for (std::size_t i = 0; i < kept_count; ++i)
    {
      kept.push_back(input[reference.order[i]]);
      reference_kept.push_back(reference_input[reference.order[i]]);
    }
    ES::Options against_input;
    against_input.reference_normal = std::array<double, 3>{ 0., 0., 1. };
    const double expected =
      CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(reference_kept, k, CGAL::parameters::default_values(),
                                                                    against_input);
    CHECK(expected > 0.);
    CHECK(expected <= std::log2(double(k + 1)) + 1e-12);
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(kept, k, CGAL::parameters::default_values(),
                                                                        against_input) == expected);
  }

  // compute_mean_normal_angle_entropy on the whole input: on a vector, on
  // pairs through a point map, on a Point_set_3, with PCA and jet normals.
  using Pair = std::pair<Point, int>;
  CGAL::Point_set_3<Point> set;
  for (const Point& p : input)
    set.insert(p);
  ES::Options jet;
  jet.normal_estimation = ES::Normal_estimation::jet;
  for (const ES::Options& options : { ES::Options(), jet })
  {
    INFO((options.normal_estimation == ES::Normal_estimation::jet ? "jet" : "pca"));
    const double expected = CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(
      reference_input, k, CGAL::parameters::default_values(), options);
    CHECK(expected > 0.);
    CHECK(expected <= std::log2(double(k + 1)) + 1e-12);
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(
            input, k, CGAL::parameters::default_values(), options) == expected);
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(
            labelled, k, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pair>()), options) ==
          expected);
    CHECK(CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(
            set, k, CGAL::parameters::default_values(), options) == expected);
  }
}
