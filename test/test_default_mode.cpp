// Tests of the default mode (Mode::weighted_elimination): its feature field
// and its removal order against a reference computed from the user manual's
// definitions with code of its own (reference_elimination.h), the guarantees
// of entropy_simplify_point_set in that mode (count, subset, permutation,
// callback, determinism, bad input), and what the mode is for: no holes, and
// more points on features.

#include <catch2/catch.hpp>

#include "reference_elimination.h"
#include "require_tbb.h"
#include "simplification_run.h"
#include "test_clouds.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/experiment_I_replica.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Coverage_elimination.h>
#include <CGAL/Entropy_simplification/internal/Weighted_elimination.h>
#include <CGAL/Entropy_simplification/internal/simplify_points.h>

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
namespace ESI = CGAL::Entropy_simplification::internal;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;

namespace {

using test_runs::Run;
using test_runs::simplify;

std::vector<std::size_t> removals(const Run& run) { return test_runs::removal_order(run); }

bool is_permutation(const Run& run, std::size_t n)
{
  return run.order.size() == n && test_runs::is_permutation_of_input(run);
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

// A sheet folded at a right angle along the crease x = z = 0, with Gaussian
// noise across each half, at random positions: no two distances tie. Without
// noise, the normal entropies are 0 off the crease and the noise floor is at
// its one-degree minimum.
test_clouds::Cloud fold(std::size_t n, double noise, std::uint64_t seed)
{
  test_clouds::Random random(seed);
  test_clouds::Cloud c{ "fold " + std::to_string(n) + " noise " + std::to_string(noise), {} };
  for (std::size_t i = 0; i < n; ++i)
  {
    const double u = 2. * random.uniform() - 1., v = random.uniform(), across = noise * random.gaussian();
    c.points.emplace_back(u < 0. ? u : across, v, u < 0. ? across : u);
  }
  return c;
}

// The paper's board and ball in 800 points, a tenth on the ball. At k = 5 the
// coarse scale (13 points) sees the ball, and the feature budget lowers the
// weight.
test_clouds::Cloud board_and_ball() { return test_clouds::small_replica(720, 80, 0.002, 11); }

struct Setting
{
  test_clouds::Cloud cloud;
  unsigned int k;
};

// The package's field before any removal, by input position, with the
// normals the package writes.
struct Field_by_position
{
  ESI::Array<ESI::Working_vector> normals;
  std::vector<double> scale;
  double effective_area = 0.;
};

template <typename ConcurrencyTag>
Field_by_position package_field(const std::vector<Point>& points, unsigned int k, const ES::Options& options)
{
  const ESI::Indexed_points indexed = ESI::sort_spatially(ESI::Array<ESI::Working_point>(points.begin(), points.end()));
  ESI::Coverage_elimination engine(indexed, k, options);
  REQUIRE(engine.initialize<ConcurrencyTag>([](double) { return true; }));
  const ESI::Elimination_field& field = engine.field();
  const ESI::Array<ESI::Working_vector> normals =
    engine.normals_of<ConcurrencyTag>(ESI::all_indices(points.size()));
  Field_by_position by_position;
  by_position.normals.resize(points.size());
  by_position.scale.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    by_position.normals[indexed.input_position[i]] = normals[i];
    by_position.scale[indexed.input_position[i]] = field.scale[i];
  }
  by_position.effective_area = field.effective_area;
  return by_position;
}

double relative_difference(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Normals up to orientation, which the field does not define; everything to
// 1e-12: the reference runs the same operations, so only a different formula
// or a different neighbourhood can tell them apart.
void check_same_field(const Field_by_position& package, const reference::Field& expected)
{
  REQUIRE(package.normals.size() == expected.normals.size());
  double normal_difference = 0., scale_difference = 0.;
  for (std::size_t p = 0; p < expected.normals.size(); ++p)
  {
    const Kernel::Vector_3 &a = package.normals[p], &b = expected.normals[p];
    normal_difference =
      (std::max)(normal_difference, std::sqrt((std::min)((a - b).squared_length(), (a + b).squared_length())));
    scale_difference = (std::max)(scale_difference, relative_difference(package.scale[p], expected.scale[p]));
  }
  CHECK(normal_difference <= 1e-12);
  CHECK(scale_difference <= 1e-12);
  CHECK(relative_difference(package.effective_area, expected.effective_area) <= 1e-12);
}

// The points whose strength the coarse scale raises above the fine scale's.
std::size_t points_raised_by_coarse_scale(const reference::Field& field)
{
  std::size_t raised = 0;
  for (std::size_t p = 0; p < field.coarse_strength.size(); ++p)
    raised += field.coarse_strength[p] > field.fine_strength[p] ? 1 : 0;
  return raised;
}

} // namespace

TEST_CASE("Default mode: the feature field equals the reference computed from the manual", "[default][reference]")
{
  test_parallel::require_tbb();
  // what the settings must cover for every piece of the field to count
  std::size_t raised_by_coarse_scale = 0;
  bool budget_lowered_the_weight = false, floor_at_one_degree = false;
  for (const Setting& setting : { Setting{ board_and_ball(), 5 }, Setting{ fold(2000, 0.003, 12), 8 },
                                  Setting{ fold(2000, 0., 13), 8 } })
    for (double feature_weight : { 3., 6., 0. })
      for (ES::Normal_estimation method : { ES::Normal_estimation::pca, ES::Normal_estimation::jet })
      {
        ES::Options options;
        options.feature_weight = feature_weight;
        options.normal_estimation = method;
        INFO(setting.cloud.name << ", k = " << setting.k << ", feature weight " << feature_weight << ", normals "
                                << int(method));
        const reference::Field expected = reference::feature_field(setting.cloud.points, setting.k, options);
        REQUIRE(expected.coarse_count >= setting.k + 1); // the coarse scale runs
        raised_by_coarse_scale += points_raised_by_coarse_scale(expected);
        budget_lowered_the_weight = budget_lowered_the_weight || expected.weight < feature_weight;
        floor_at_one_degree = floor_at_one_degree || expected.floor == reference::noise_floor({ 0. });

        check_same_field(package_field<CGAL::Sequential_tag>(setting.cloud.points, setting.k, options), expected);
        check_same_field(test_parallel::on_two_threads_or_more([&] {
                           return package_field<test_parallel::Parallel_tag>(setting.cloud.points, setting.k, options);
                         }),
                         expected);
      }
  CHECK(raised_by_coarse_scale > 0);
  CHECK(budget_lowered_the_weight);
  CHECK(floor_at_one_degree);
}

TEST_CASE("Default mode: the removal order equals the reference's, sequentially and in parallel",
          "[default][reference]")
{
  test_parallel::require_tbb();
  for (const Setting& setting : { Setting{ board_and_ball(), 5 }, Setting{ fold(800, 0.003, 12), 5 } })
    for (double feature_weight : { 3., 6., 0. })
      for (ES::Normal_estimation method : { ES::Normal_estimation::pca, ES::Normal_estimation::jet })
        // several stages: 800 points to 400, 200, then 160; one stage to 640,
        // with the eighth power of the weight (it keeps more than 55%)
        for (std::size_t target : { setting.cloud.points.size() / 5, setting.cloud.points.size() * 4 / 5 })
        {
          ES::Options options;
          options.feature_weight = feature_weight;
          options.normal_estimation = method;
          INFO(setting.cloud.name << ", k = " << setting.k << ", feature weight " << feature_weight << ", normals "
                                  << int(method) << ", target " << target);
          const reference::Field field = reference::feature_field(setting.cloud.points, setting.k, options);
          REQUIRE(field.coarse_count >= setting.k + 1);
          const std::vector<std::size_t> expected = reference::removal_order(setting.cloud.points, field, target);

          const auto np = CGAL::parameters::number_of_output_points(target);
          const Run sequential = simplify<CGAL::Sequential_tag>(setting.cloud.points, setting.k, np, options);
          CHECK(sequential.kept == target);
          CHECK(removals(sequential) == expected);
          const Run parallel = test_parallel::on_two_threads_or_more(
            [&] { return simplify<test_parallel::Parallel_tag>(setting.cloud.points, setting.k, np, options); });
          CHECK(removals(parallel) == expected);
        }
}

TEST_CASE("Default mode: the removal order equals the reference's on tied distances and small clouds",
          "[default][reference]")
{
  // Small clouds, below the coarse scale: a grid whose distances tie, every
  // tie broken by input position, a volume without surface, a small surface.
  // The last one has a stray point far away, whose area counts for 1000
  // medians only.
  test_clouds::Cloud stray = test_clouds::wavy_surface(200, 0.01, 3);
  stray.name += " and a stray point";
  stray.points.emplace_back(500., 500., 500.);
  const std::vector<test_clouds::Cloud> clouds = { test_clouds::bent_grid(14), test_clouds::cube_volume(150, 3),
                                                   test_clouds::wavy_surface(200, 0.01, 2), stray };
  for (const test_clouds::Cloud& cloud : clouds)
    for (double feature_weight : { 0., 3. })
      for (ES::Normal_estimation method : { ES::Normal_estimation::pca, ES::Normal_estimation::jet })
        // one stage, several stages halving the count, one stage keeping
        // more than 55% (the eighth power of the weight)
        for (std::size_t tenths : { std::size_t(5), std::size_t(1), std::size_t(8) })
        {
          ES::Options options;
          options.feature_weight = feature_weight;
          options.normal_estimation = method;
          const unsigned int k = 8;
          const std::size_t target = cloud.points.size() * tenths / 10;
          INFO(cloud.name << ", feature weight " << feature_weight << ", normals " << int(method) << ", target "
                          << target);
          const std::vector<std::size_t> expected =
            reference::removal_order(cloud.points, reference::feature_field(cloud.points, k, options), target);
          const Run run = simplify(cloud.points, k, CGAL::parameters::number_of_output_points(target), options);
          CHECK(run.kept == target);
          CHECK(removals(run) == expected);
        }
  // the fewest neighbours: below and at the three nearest that the
  // elimination takes from the field's neighbour table rather than search
  for (unsigned int k : { 2u, 3u })
  {
    INFO("k = " << k);
    const std::vector<Point>& points = clouds[2].points;
    const std::size_t target = points.size() / 10;
    const std::vector<std::size_t> expected =
      reference::removal_order(points, reference::feature_field(points, k, ES::Options()), target);
    const auto np = CGAL::parameters::number_of_output_points(target);
    CHECK(removals(simplify(points, k, np)) == expected);
    CHECK(removals(test_parallel::on_two_threads_or_more(
            [&] { return simplify<test_parallel::Parallel_tag>(points, k, np); })) == expected);
  }
}

namespace {

// The reference's terms, as the library's.
reference::Terms reference_terms(const ESI::Default_mode_terms& t)
{
  reference::Terms r;
  r.coarse_scale = t.coarse_scale;
  r.feature_budget = t.feature_budget;
  r.strong_features_first = t.strong_features_first;
  r.relocation = t.relocation;
  r.medians = t.medians;
  r.radius_bound = t.radius_bound;
  r.coverage_swaps = t.coverage_swaps;
  r.coverage_elimination = t.coverage_elimination;
  return r;
}

std::vector<std::size_t> as_positions(const ESI::Array<ESI::Index>& removed)
{
  return std::vector<std::size_t>(removed.begin(), removed.end());
}

} // namespace

// The benchmark's ablation switches each term off in turn: the library then
// still equals the reference, which leaves the term out with code of its own,
// and each switch changes the removal order of at least one cloud, so that a
// switch that did nothing would fail.
TEST_CASE("Default mode: with each term switched off, the removal order equals the reference's",
          "[default][reference][ablation]")
{
  test_parallel::require_tbb();
  ES::Options options;
  const std::vector<Setting> settings = { Setting{ board_and_ball(), 5 }, Setting{ fold(800, 0.003, 12), 5 },
                                          Setting{ test_clouds::wavy_surface(600, 0.01, 4), 8 } };
  std::vector<ESI::Term_switched_off> ablation = ESI::each_term_switched_off();
  REQUIRE(ablation.size() == 8);
  ablation.insert(ablation.begin(), { "none", ESI::Default_mode_terms() });
  std::vector<std::vector<std::size_t> > with_all_terms;
  for (const ESI::Term_switched_off& off : ablation)
  {
    const reference::Terms reference_off = reference_terms(off.terms);
    const std::string term = off.term;
    bool changes_an_order = false;
    for (std::size_t s = 0; s < settings.size(); ++s)
    {
      const std::vector<Point>& points = settings[s].cloud.points;
      const std::size_t target = points.size() / 5;
      INFO(settings[s].cloud.name << ", term switched off: " << term);
      const std::vector<std::size_t> expected = reference::removal_order(
        points, reference::feature_field(points, settings[s].k, options, reference_off), target, reference_off);
      const ESI::Array<ESI::Working_point> input(points.begin(), points.end());
      CHECK(as_positions(ESI::removal_order_with_terms<CGAL::Sequential_tag>(input, settings[s].k, target, options,
                                                                            off.terms)) == expected);
      CHECK(as_positions(test_parallel::on_two_threads_or_more([&] {
              return ESI::removal_order_with_terms<test_parallel::Parallel_tag>(input, settings[s].k, target,
                                                                                options, off.terms);
            })) == expected);
      if (term == "none")
      {
        CHECK(expected == removals(simplify(points, settings[s].k,
                                            CGAL::parameters::number_of_output_points(target), options)));
        with_all_terms.push_back(expected);
      }
      changes_an_order = changes_an_order || expected != with_all_terms[s];
    }
    if (term != "none")
      CHECK(changes_an_order);
  }
}

namespace {

ESI::Default_mode_terms with_weighted_sample_elimination()
{
  ESI::Default_mode_terms terms;
  terms.coverage_elimination = false;
  return terms;
}

// The library's ranks with the `terms`, through the kept points from `level`:
// the removal order, the one point never removed last.
template <typename ConcurrencyTag>
std::vector<std::size_t> ranks_with_terms(const std::vector<Point>& points, unsigned int k, std::size_t level,
                                          const ES::Options& options, const ESI::Default_mode_terms& terms)
{
  const auto removed = ESI::simplify_points<ConcurrencyTag>(
    ESI::collapse_duplicates<ConcurrencyTag>(ESI::Array<ESI::Working_point>(points.begin(), points.end())), k, level,
    ESI::Run_extent::through_the_kept, options, std::function<bool(double)>(), false,
    [](ESI::Index, const ESI::Working_vector&) {}, terms);
  REQUIRE(removed);
  std::vector<std::size_t> rank(points.size(), 0);
  for (std::size_t j = 0; j < removed->size(); ++j)
    rank[(*removed)[j]] = points.size() - 1 - j;
  return rank;
}

} // namespace

// Either elimination against the reference's scans from scratch (each round
// of the greedy coverage elimination, each removal of weighted sample
// elimination): the removal order to a tenth, a fifth, a half and nine
// tenths (the greedy elimination's three exponents, see
// coverage_weight_exponent), and
// the ranks through the kept points from a fifth, sequentially and in
// parallel. A stray point thousands of spacings away, and one so far that
// its shares reach their bound (see largest_share); a grid whose costs all
// tie.
TEST_CASE("Default mode: with either elimination, removal order and ranks equal the reference's",
          "[default][reference][coverage elimination]")
{
  test_parallel::require_tbb();
  for (const ESI::Default_mode_terms& terms : { ESI::Default_mode_terms(), with_weighted_sample_elimination() })
  {
    const reference::Terms reference_with = reference_terms(terms);
    test_clouds::Cloud stray = test_clouds::wavy_surface(300, 0.01, 3);
    stray.name += " and a stray point";
    test_clouds::Cloud far_stray = stray;
    far_stray.name += ", far";
    stray.points.emplace_back(500., 500., 500.);
    far_stray.points.emplace_back(1e9, 1e9, 1e9);
    const std::vector<Setting> settings = { Setting{ board_and_ball(), 5 }, Setting{ fold(800, 0.003, 12), 5 },
                                            Setting{ test_clouds::bent_grid(20), 8 }, Setting{ stray, 8 },
                                            Setting{ far_stray, 8 } };
    for (const Setting& setting : settings)
      for (double feature_weight : { 3., 0. })
      {
        ES::Options options;
        options.feature_weight = feature_weight;
        const std::vector<Point>& points = setting.cloud.points;
        const reference::Field field = reference::feature_field(points, setting.k, options, reference_with);
        const ESI::Array<ESI::Working_point> input(points.begin(), points.end());
        for (std::size_t tenths : { std::size_t(1), std::size_t(2), std::size_t(5), std::size_t(9) })
        {
          const std::size_t target = points.size() * tenths / 10;
          INFO(setting.cloud.name << ", feature weight " << feature_weight << ", target " << target
                                  << (terms.coverage_elimination ? "" : ", weighted sample elimination"));
          const std::vector<std::size_t> expected = reference::removal_order(points, field, target, reference_with);
          CHECK(as_positions(ESI::removal_order_with_terms<CGAL::Sequential_tag>(input, setting.k, target, options,
                                                                                terms)) == expected);
          CHECK(as_positions(test_parallel::on_two_threads_or_more([&] {
                  return ESI::removal_order_with_terms<test_parallel::Parallel_tag>(input, setting.k, target, options,
                                                                                    terms);
                })) == expected);
        }
        const std::size_t level = points.size() / 5;
        INFO(setting.cloud.name << ", feature weight " << feature_weight << ", ranks from " << level
                                << (terms.coverage_elimination ? "" : ", weighted sample elimination"));
        const std::vector<std::size_t> expected = reference::ranks(points, field, level, reference_with);
        CHECK(ranks_with_terms<CGAL::Sequential_tag>(points, setting.k, level, options, terms) == expected);
        CHECK(test_parallel::on_two_threads_or_more([&] {
                return ranks_with_terms<test_parallel::Parallel_tag>(points, setting.k, level, options, terms);
              }) == expected);
      }
  }
}

namespace {

// What the library's coverage swaps leave, by input position: the points
// present, and each point's nearest present point.
struct Swapped
{
  std::vector<bool> present;
  std::vector<std::size_t> nearest;
  bool operator==(const Swapped& other) const { return present == other.present && nearest == other.nearest; }
};

// The library's coverage swaps, each point's `scale` given by input
// position.
template <typename ConcurrencyTag>
Swapped swapped_by_the_library(const std::vector<Point>& points, const std::vector<bool>& present, std::size_t swaps,
                               const std::vector<double>& scale)
{
  const ESI::Indexed_points indexed =
    ESI::sort_spatially<ConcurrencyTag>(ESI::Array<ESI::Working_point>(points.begin(), points.end()));
  ESI::Array<char> flags(points.size());
  ESI::Array<double> scale_of(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    flags[i] = present[indexed.input_position[i]];
    scale_of[i] = scale[indexed.input_position[i]];
  }
  const ESI::Array<ESI::Index> site = ESI::swap_farthest_for_crowded<ConcurrencyTag>(indexed, flags, swaps, scale_of);
  Swapped result{ std::vector<bool>(points.size()), std::vector<std::size_t>(points.size()) };
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    result.present[indexed.input_position[i]] = flags[i] != 0;
    result.nearest[indexed.input_position[i]] = indexed.input_position[site[i]];
  }
  return result;
}

double greatest_squared_distance(const std::vector<Point>& points, const std::vector<bool>& present)
{
  double greatest = 0.;
  for (std::size_t p = 0; p < points.size(); ++p)
    greatest = (std::max)(greatest, reference::squared_distance_to_present(points, present, p));
  return greatest;
}

} // namespace

TEST_CASE("Default mode: the coverage swaps equal the reference's, and never widen the greatest gap",
          "[default][reference][coverage]")
{
  test_parallel::require_tbb();
  // Present points from a plain thinning, clustered so that gaps and crowds
  // both occur: every third point, and every point of a dense patch. The
  // scales, as the field's, are rounded to 30 bits; uneven, they reorder
  // the crowded points.
  for (const test_clouds::Cloud& cloud : { fold(3000, 0.003, 21), test_clouds::wavy_surface(2500, 0.01, 22) })
    for (bool even_scales : { true, false })
      for (std::size_t swaps : { std::size_t(1), std::size_t(7), std::size_t(60) })
      {
        const std::vector<Point>& points = cloud.points;
        std::vector<bool> present(points.size());
        std::vector<double> scale(points.size(), 1.);
        for (std::size_t p = 0; p < points.size(); ++p)
        {
          present[p] = p % 3 == 0 || (p % 7 == 1 && points[p].x() < points[0].x());
          if (!even_scales)
            scale[p] = 0.5 + double(p % 5) / 8.;
        }
        INFO(cloud.name << ", " << (even_scales ? "even" : "uneven") << " scales, " << swaps << " swaps");
        std::vector<bool> expected = present;
        reference::swap_farthest_for_crowded(points, expected, swaps, scale);
        CHECK(expected != present);
        CHECK(std::count(expected.begin(), expected.end(), true) == std::count(present.begin(), present.end(), true));
        CHECK(greatest_squared_distance(points, expected) <= greatest_squared_distance(points, present));
        // the nearest present points too: a ranking's levels of detail start from them
        const Swapped expected_with_nearest{ expected, reference::cells_of_present(points, expected) };
        CHECK(swapped_by_the_library<CGAL::Sequential_tag>(points, present, swaps, scale) == expected_with_nearest);
        CHECK(test_parallel::on_two_threads_or_more([&] {
                return swapped_by_the_library<test_parallel::Parallel_tag>(points, present, swaps, scale);
              }) == expected_with_nearest);
      }
}

TEST_CASE("Default mode: the swaps' searches find the present points whether or not their tree holds them",
          "[default][reference][coverage]")
{
  // A tenth of the points present, and a few far ones offered to the tree;
  // then points made present and absent at random, most of them ones the
  // tree does not hold, so that they are listed apart, the list is built
  // into the tree again, and points listed apart leave it.
  const test_clouds::Cloud cloud = test_clouds::wavy_surface(2000, 0.01, 41);
  const ESI::Indexed_points indexed =
    ESI::sort_spatially<CGAL::Sequential_tag>(ESI::Array<ESI::Working_point>(cloud.points.begin(), cloud.points.end()));
  const ESI::Index n = ESI::Index(indexed.size());
  ESI::Array<char> present(n, 0);
  for (ESI::Index i = 0; i < n; i += 10)
    present[i] = 1;
  ESI::Tree_search<CGAL::Sequential_tag> search(indexed, present,
                                                ESI::nearest_present_points<CGAL::Sequential_tag>(indexed, present));
  std::vector<ESI::Neighbor> offered;
  for (ESI::Index i = 5; i < n; i += 100)
    offered.push_back(ESI::Neighbor{ 0., indexed.input_position[i], i });
  search.may_become_present(offered);
  const auto brute_force = [&](ESI::Index q, ESI::Index excluded) {
    ESI::Neighbor best = ESI::no_neighbor();
    for (ESI::Index j = 0; j < n; ++j)
      if (present[j] && j != q && j != excluded)
        best = (std::min)(best, ESI::Neighbor{ ESI::squared_distance(indexed.points[q], indexed.points[j]),
                                               indexed.input_position[j], j });
    return best.id;
  };
  test_clouds::Random random(42);
  std::vector<ESI::Index> brought; // the points made present here
  std::size_t mismatches = 0, checks = 0, made_absent = 0;
  for (int step = 0; step < 400; ++step)
  {
    if (step % 3 != 2)
    {
      ESI::Index p;
      do
        p = ESI::Index(random.below(n));
      while (present[p]);
      present[p] = 1;
      search.made_present(p);
      brought.push_back(p);
    }
    else
    {
      const ESI::Index p = step % 2 ? brought[random.below(brought.size())] : ESI::Index(10 * random.below(n / 10));
      if (!present[p])
        continue;
      present[p] = 0;
      search.made_absent(p);
      ++made_absent;
    }
    for (ESI::Index q = ESI::Index(step % 7); q < n; q += 53)
    {
      const ESI::Index excluded = ESI::Index(random.below(n));
      mismatches += search.nearest_but(q, excluded).id != brute_force(q, excluded);
      ++checks;
    }
  }
  CHECK(made_absent > 100);
  CHECK(checks > 10000);
  CHECK(mismatches == 0);
}

TEST_CASE("Default mode: a coverage swap that would widen a gap is not made", "[default][reference][coverage]")
{
  // Evenly spaced on a line, every other point present: the farthest point
  // (1) would come in, but every present point leaving would leave a point
  // as far as the farthest then is (3, at 1), so nothing changes.
  const std::vector<Point> line = { Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(3, 0, 0), Point(4, 0, 0) };
  const std::vector<bool> present = { true, false, true, false, true };
  const std::vector<double> unit(6, 1.);
  std::vector<bool> expected = present;
  reference::swap_farthest_for_crowded(line, expected, 3, unit);
  CHECK(expected == present);
  // each point's nearest present point too, ties to the lower input position
  CHECK(swapped_by_the_library<CGAL::Sequential_tag>(line, present, 3, unit) ==
        Swapped{ present, { 0, 0, 2, 2, 4 } });
  // Two crowded points (0 and 1) and a gap: the farthest point (5) comes in
  // and the most crowded (0) leaves for it. A second swap would bring 4 in,
  // but 1 is no longer crowded and 3 cannot leave: the swaps end there.
  const std::vector<Point> gap = { Point(0, 0, 0), Point(0.2, 0, 0), Point(0.4, 0, 0),
                                   Point(3, 0, 0), Point(4, 0, 0),   Point(5, 0, 0) };
  const std::vector<bool> before = { true, true, false, true, false, false };
  const std::vector<bool> after = { false, true, false, true, false, true };
  // With 0's scale halved, 0 is four times less crowded than 1, which leaves
  // instead (2 then lies at 0.4 from 0). A second swap would bring 4 in, but
  // 0 is now less crowded than it was, and 3 cannot leave.
  std::vector<double> halved = unit;
  halved[0] = 0.5;
  const std::vector<bool> after_halved = { true, false, false, true, false, true };
  for (std::size_t swaps : { 1, 2 })
  {
    std::vector<bool> swapped = before;
    reference::swap_farthest_for_crowded(gap, swapped, swaps, unit);
    CHECK(swapped == after);
    CHECK(swapped_by_the_library<CGAL::Sequential_tag>(gap, before, swaps, unit) ==
          Swapped{ after, { 1, 1, 1, 3, 3, 5 } });
    swapped = before;
    reference::swap_farthest_for_crowded(gap, swapped, swaps, halved);
    CHECK(swapped == after_halved);
    CHECK(swapped_by_the_library<CGAL::Sequential_tag>(gap, before, swaps, halved) ==
          Swapped{ after_halved, { 0, 0, 0, 3, 3, 5 } });
  }
  // Every point present, or a single one: no swap.
  const std::vector<bool> all(5, true), one = { false, false, true, false, false };
  CHECK(swapped_by_the_library<CGAL::Sequential_tag>(line, all, 3, unit) == Swapped{ all, { 0, 1, 2, 3, 4 } });
  CHECK(swapped_by_the_library<CGAL::Sequential_tag>(line, one, 3, unit) == Swapped{ one, { 2, 2, 2, 2, 2 } });
}

namespace {

// The removals of an engine that gathers `leaves_per_block` leaves at a time.
std::vector<ESI::Index> engine_removals(const ESI::Indexed_points& indexed, unsigned int k, std::size_t target,
                                        std::size_t leaves_per_block)
{
  return test_parallel::on_two_threads_or_more([&] {
    ESI::Weighted_elimination engine(indexed, k, ES::Options(), ESI::Default_mode_terms(), leaves_per_block);
    REQUIRE(engine.initialize<test_parallel::Parallel_tag>([](double) { return true; }));
    std::vector<ESI::Index> removed;
    REQUIRE(engine.remove_down_to<test_parallel::Parallel_tag>(target, [&](ESI::Index p) {
      removed.push_back(p);
      return true;
    }));
    return removed;
  });
}

} // namespace

TEST_CASE("Default mode: the neighbour lists do not depend on how many leaves a block gathers",
          "[default][reference]")
{
  // 20,000 points: one block holds all the tree's leaves, as on the clouds
  // of the reference tests above; blocks of one leaf or seven append
  // thousands of lists, in parallel, each at its own offset.
  const test_clouds::Cloud cloud = fold(20000, 0.003, 13);
  const ESI::Indexed_points indexed =
    ESI::sort_spatially(ESI::Array<ESI::Working_point>(cloud.points.begin(), cloud.points.end()));
  const std::size_t target = cloud.points.size() / 10;
  const std::vector<ESI::Index> one_block = engine_removals(indexed, 10, target, std::size_t(1) << 20);
  REQUIRE(one_block.size() == cloud.points.size() - target);
  CHECK(engine_removals(indexed, 10, target, 1) == one_block);
  CHECK(engine_removals(indexed, 10, target, 7) == one_block);
}

TEST_CASE("Default mode: weights round as std::llround does, halves and their neighbours included",
          "[default][reference]")
{
  std::vector<double> values = { 0., 0.25, 0.5, 1.5, 2.5, 1099511627775.5, 1099511627776., 4503599627370495.5 };
  test_clouds::Random random(3);
  for (int i = 0; i < 100000; ++i)
  {
    const double scale = std::ldexp(1., int(random.below(53)));
    values.push_back(random.uniform() * scale);
    values.push_back(std::floor(random.uniform() * scale) + 0.5); // a half, exact below 2^52
  }
  const std::size_t exact = values.size();
  for (std::size_t i = 0; i < exact; ++i)
    for (double toward : { 0., std::ldexp(1., 53) })
      values.push_back(std::nextafter(values[i], toward));
  for (double x : values)
    if (x < std::ldexp(1., 53))
      REQUIRE(ESI::rounded(x) == std::llround(x));
}

TEST_CASE("Default mode: exact count, a subset, nothing lost, deterministic", "[default][guarantees]")
{
  test_parallel::require_tbb();
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
  const Run parallel =
    test_parallel::on_two_threads_or_more([&] { return simplify<test_parallel::Parallel_tag>(points, 10, np); });
  CHECK(parallel.order == first.order);
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

TEST_CASE("Default mode: a greater feature weight keeps more on features, even where the budget lowers it",
          "[default][quality]")
{
  // the paper's ball on a board of 50 cm instead of 60, so that the ball
  // takes enough of the area for the budget to lower the weight
  ES::Experiment_I_setup setup;
  setup.board_points = 3600;
  setup.sphere_points = 1200;
  setup.board_size = 0.5;
  setup.range_noise = 0.002;
  setup.seed = 5;
  std::vector<std::pair<Point, int> > labelled;
  ES::experiment_I_replica<Point>(std::back_inserter(labelled), setup);
  std::vector<Point> points;
  for (const auto& p : labelled)
    points.push_back(p.first);
  const auto kept_on_ball = [&](double feature_weight) {
    ES::Options options;
    options.feature_weight = feature_weight;
    const Run run = simplify(points, 10, CGAL::parameters::number_of_output_points(400), options);
    std::size_t count = 0;
    for (std::size_t j = 0; j < run.kept; ++j)
      count += labelled[run.order[j]].second == ES::sphere_label ? 1 : 0;
    return count;
  };
  ES::Options options;
  options.feature_weight = 3.;
  const double budgeted = reference::feature_field(points, 10, options).weight;
  INFO("the weight after the budget: " << budgeted);
  REQUIRE(budgeted < 3.);
  const std::size_t at_0 = kept_on_ball(0.), at_3 = kept_on_ball(3.), at_6 = kept_on_ball(6.);
  INFO("kept on the ball: " << at_0 << ", " << at_3 << ", " << at_6 << " at weights 0, 3, 6");
  CHECK(at_0 < at_3);
  CHECK(at_3 < at_6);
}

TEST_CASE("Default mode: a stray point far from the cloud neither widens every neighbourhood nor spoils the rest",
          "[default][bad input]")
{
  // Counted in full, the stray point's area made every stage's radius as wide
  // as its distance: each point then had all others within reach (a run
  // quadratic in time and memory: 12.8 s instead of 0.09 s on these
  // 20,000 points), their weights all tied, and the kept points fitted the cloud's
  // planes worse.
  const std::vector<Point> cloud = fold(20000, 0.003, 21).points;
  std::vector<Point> with_stray = cloud;
  with_stray.emplace_back(1e4, 1e4, 1e4);
  const Run plain = simplify(cloud, 10, CGAL::parameters::number_of_output_points(2000));
  const Run stray = simplify(with_stray, 10, CGAL::parameters::number_of_output_points(2001));
  // isolated, the stray point has no neighbour within reach, so it is kept
  const auto kept_stray = stray.order.begin() + std::ptrdiff_t(stray.kept);
  REQUIRE(std::find(stray.order.begin(), kept_stray, cloud.size()) != kept_stray);
  const auto quality_on_the_cloud = [&](const Run& run) {
    std::vector<Point> kept;
    for (std::size_t j = 0; j < run.kept; ++j)
      if (run.order[j] < cloud.size())
        kept.push_back(cloud[run.order[j]]);
    return CGAL::measure_simplification_quality<CGAL::Sequential_tag>(cloud, kept);
  };
  const ES::Quality_report without = quality_on_the_cloud(plain), with = quality_on_the_cloud(stray);
  INFO("without and with the stray point: point-to-plane error " << without.point_to_plane << ", "
                                                                  << with.point_to_plane << "; largest distance "
                                                                  << without.max_distance << ", " << with.max_distance);
  // counted in full, the stray point made them 1.13 and 1.36 times as large
  CHECK(with.point_to_plane <= 1.05 * without.point_to_plane);
  CHECK(with.max_distance <= 1.05 * without.max_distance);
  CHECK(with.mean_distance <= 1.05 * without.mean_distance);
}

TEST_CASE("Default mode: bad input gets a documented behaviour", "[default][bad input]")
{
  const std::vector<Point> points = test_clouds::wavy_surface(300, 0.01, 17).points;
  const auto count = [](std::size_t n) { return CGAL::parameters::number_of_output_points(n); };
  SECTION("a feature weight that is negative, above 100 or not finite is an error, before anything moves")
  {
    for (double bad : { -1., 100.5, 1e308, std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity() })
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
  SECTION("jet normals on a cluster narrower than 1e-150 in a wider cloud: null normals there, no crash")
  {
    // the fit's scaling underflowed on such a cluster, and its SVD read out
    // of bounds: a crash with the cluster's spacing below about 1e-162, which
    // is now rejected (points too near to be told apart); at 1e-153 the
    // points are told apart, and the cluster is still narrower than 1e-150
    std::vector<Point> clustered;
    for (int i = 0; i < 11; ++i)
      clustered.emplace_back(0.25, double(i) * 1e-153, double(i % 7) * 1e-153);
    clustered.emplace_back(1., 1., 1.);
    ES::Options jet;
    jet.normal_estimation = ES::Normal_estimation::jet;
    const Run once = simplify(clustered, 10, count(6), jet);
    CHECK(once.kept == 6);
    CHECK(is_permutation(once, clustered.size()));
    CHECK(once.order == simplify(clustered, 10, count(6), jet).order);
    jet.mode = ES::Mode::paper;
    CHECK(simplify(clustered, 10, count(11), jet).kept == 11);
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
