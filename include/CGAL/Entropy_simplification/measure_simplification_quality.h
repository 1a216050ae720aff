// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality of a simplification measured against its input: how far the
// input points lie from the kept points, and from the surface these span.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_MEASURE_SIMPLIFICATION_QUALITY_H
#define CGAL_ENTROPY_SIMPLIFICATION_MEASURE_SIMPLIFICATION_QUALITY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Distinct_points.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>
#include <CGAL/Entropy_simplification/internal/named_parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Entropy_simplification {

/**
   \ingroup PkgEntropySimplificationRef

   The quality of a simplification, as `CGAL::measure_simplification_quality()`
   measures it. The distances are divided by the diagonal of the input's
   bounding box, as in `benchmark/README.md`, so that clouds of any size and
   unit compare; when all the input points coincide (a diagonal of 0), they
   are given undivided.
*/
struct Quality_report
{
  /// the mean, over the input points, of the distance to the nearest kept point
  double mean_distance = 0.;
  /// the greatest of these distances: the one-sided Hausdorff distance from
  /// the input to the kept points
  double max_distance = 0.;
  /// the root mean square distance from each input point to the plane fitted
  /// (by PCA) to the 10 kept points nearest its nearest kept point, that
  /// point included (to all of them when fewer are kept); where these kept
  /// points lie on one line (exactly, as copies of two points do), the
  /// distance to that line, and where they coincide, the distance to them.
  /// Not a number when fewer than 3 points are kept, as they span no plane.
  double point_to_plane = 0.;
  /// the diagonal of the input's bounding box, in the input's unit
  double diagonal = 0.;
  /// the number of input points
  std::size_t input_size = 0;
  /// the number of kept points
  std::size_t kept_size = 0;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The kept points nearest a kept point, itself included, span its plane.
constexpr unsigned int quality_plane_points = 10;

inline double bounding_box_diagonal(const Array<Working_point>& points)
{
  double low[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, high[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const Working_point& p : points)
    for (int d = 0; d < 3; ++d)
    {
      low[d] = (std::min)(low[d], p.cartesian(d));
      high[d] = (std::max)(high[d], p.cartesian(d));
    }
  return std::sqrt((high[0] - low[0]) * (high[0] - low[0]) + (high[1] - low[1]) * (high[1] - low[1]) +
                   (high[2] - low[2]) * (high[2] - low[2]));
}

// The input points, then the kept ones, in one set sorted in kd order, each
// with its position in that concatenation: a tree of the kept ones (the
// positions from the input's size on) then answers the queries of both, ties
// going to the first kept point. Unsorted, the tree's boxes would overlap and
// every search would visit most of the kept points.
template <typename ConcurrencyTag>
Indexed_points input_then_kept(const Array<Working_point>& input, const Array<Working_point>& kept)
{
  if (input.size() + kept.size() >= std::size_t((std::numeric_limits<Index>::max)()))
    throw std::invalid_argument("measure_simplification_quality: the input and the kept points together must "
                                "number fewer than 2^32 - 1");
  Array<Working_point> both;
  both.reserve(input.size() + kept.size());
  both.insert(both.end(), input.begin(), input.end());
  both.insert(both.end(), kept.begin(), kept.end());
  return sort_spatially<ConcurrencyTag>(std::move(both));
}

struct Local_plane
{
  Working_vector normal; // unit, or null where the points span no plane
  Working_vector line;   // along the points where they lie on one line, or null
  Working_point centroid;
};

// The plane of the `m` points, or where they span none, their line or their
// common point, told apart exactly: PCA's normal is then any of several,
// and rounding (in the centroid of copies, say) would pick one.
template <typename PointAt>
Local_plane local_plane(std::size_t m, PointAt point)
{
  Local_plane plane{ CGAL::NULL_VECTOR, CGAL::NULL_VECTOR, point(0) };
  std::size_t other = 1;
  while (other < m && point(other) == point(0))
    ++other;
  if (other == m)
    return plane;
  using Exact_predicates = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto exact = [&](std::size_t j) { return Exact_predicates::Point_3(point(j).x(), point(j).y(), point(j).z()); };
  std::size_t j = other + 1;
  while (j < m && CGAL::collinear(exact(0), exact(other), exact(j)))
    ++j;
  plane.centroid = centroid_of(m, point);
  if (j == m)
    plane.line = point(other) - point(0);
  else
    plane.normal = pca_normal(m, point);
  return plane;
}

// The plane of each kept point, from it and its nearest kept points, by its
// rank among the kept ones (its position in `all` less `input_size`).
template <typename ConcurrencyTag>
Array<Local_plane> kept_planes(const Indexed_points& all, const Array<Index>& kept_ids, std::size_t input_size,
                               const Point_tree& kept_tree)
{
  const std::size_t m = kept_ids.size();
  const unsigned int others = unsigned((std::min)(std::size_t(quality_plane_points), m)) - 1;
  Array<Index> near;
  nearest_neighbor_table<ConcurrencyTag>(kept_tree, kept_ids, others, near, [](std::size_t) { return true; });
  Array<Local_plane> planes(m);
  for_each_index<ConcurrencyTag>(
    m,
    [&](std::size_t r) {
      const Index c = kept_ids[r];
      auto point = [&](std::size_t j) -> const Working_point& {
        return all.points[j == 0 ? c : near[r * others + j - 1]];
      };
      planes[all.input_position[c] - input_size] = local_plane(others + 1, point);
    },
    [](std::size_t) { return true; });
  return planes;
}

// Where the kept points span no plane, the distance to their line or common
// point stands for the plane's. Lengths by std::hypot, as squares of
// coordinates near the bounds the package accepts would overflow or
// underflow.
inline double distance_to_plane(const Working_point& p, const Local_plane& plane)
{
  const Working_vector offset = p - plane.centroid;
  auto length = [](const Working_vector& v) { return std::hypot(v.x(), v.y(), v.z()); };
  if (plane.line != CGAL::NULL_VECTOR)
  {
    const Working_vector along = plane.line / length(plane.line);
    return length(offset - (offset * along) * along);
  }
  if (plane.normal == CGAL::NULL_VECTOR)
    return length(offset);
  return std::abs(offset * plane.normal);
}

} // namespace internal
/// \endcond
} // namespace Entropy_simplification

/**
   \ingroup PkgEntropySimplificationRef

   Measures a simplification against its input: for each input point, the
   distance to the nearest kept point and to the plane the kept points span
   there (see `Entropy_simplification::Quality_report`). The kept points need
   not be a subset of the input, so that the simplifications of other
   methods, which may move points, measure alike. No peer library reports
   this; it tells which ratio a cloud can take.

   \tparam ConcurrencyTag enables sequential versus parallel searches:
   `Sequential_tag`, `Parallel_tag` or `Parallel_if_available_tag`. The
   report does not depend on it: ties between kept points at the same
   distance go to the first in the range, and the sums run in input order.
   \tparam InputRange, KeptRange models of `Range`, whose iterators' value
   types are the key types of the respective point maps

   \param input the input of the simplification
   \param kept the points the simplification kept
   \param input_np, kept_np sequences of \ref bgl_namedparameters "Named
   Parameters" among the ones listed below, for `input` and `kept`
   respectively

   \cgalNamedParamsBegin
     \cgalParamNBegin{point_map}
       \cgalParamDescription{a property map associating points to the elements of the range}
       \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
       \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`, or the point
                         map of a `CGAL::Point_set_3`}
     \cgalParamNEnd
     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \return the report, its distances divided by the input's bounding-box
   diagonal

   \throw std::invalid_argument when either range is empty, when the two
   together hold 2^32 - 1 points or more (copies of a kept point past its
   tenth aside), when a coordinate is not finite or exceeds 1e150 in
   magnitude, when either range spans less than 1e-150 along every axis but
   more than 0, or when two distinct kept points lie closer than about
   1.5e-154 to each other (coincident points, in any number, are accepted).
*/
template <typename ConcurrencyTag, typename InputRange, typename KeptRange,
          typename InputNamedParameters = parameters::Default_named_parameters,
          typename KeptNamedParameters = parameters::Default_named_parameters>
Entropy_simplification::Quality_report
measure_simplification_quality(const InputRange& input, const KeptRange& kept,
                               const InputNamedParameters& input_np = parameters::default_values(),
                               const KeptNamedParameters& kept_np = parameters::default_values())
{
  namespace ES = Entropy_simplification::internal;
  static_assert(ES::Uses_only_named_parameters<InputNamedParameters, internal_np::point_t,
                                               internal_np::geom_traits_t>::value &&
                  ES::Uses_only_named_parameters<KeptNamedParameters, internal_np::point_t,
                                                 internal_np::geom_traits_t>::value,
                "measure_simplification_quality() reads only the named parameters point_map and geom_traits");

  const ES::First_touch_scope<ConcurrencyTag> first_touch;
  const ES::Array<ES::Working_point> input_points = ES::working_points(input, input_np);
  ES::Array<ES::Working_point> kept_points = ES::working_points(kept, kept_np);
  if (input_points.empty() || kept_points.empty())
    throw std::invalid_argument(std::string("measure_simplification_quality: the ") +
                                (input_points.empty() ? "input" : "simplification") + " is empty");
  Entropy_simplification::Quality_report report;
  report.input_size = input_points.size();
  report.kept_size = kept_points.size();
  // Past the first few of a group of coincident kept points, a copy is no
  // input point's nearest, ties going to the first, nor on any plane.
  kept_points = ES::limit_copies<ConcurrencyTag>(std::move(kept_points), ES::quality_plane_points).points;
  report.diagonal = ES::bounding_box_diagonal(input_points);

  const std::size_t n = report.input_size;
  const ES::Indexed_points all = ES::input_then_kept<ConcurrencyTag>(input_points, kept_points);
  ES::Array<ES::Index> kept_ids;
  kept_ids.reserve(kept_points.size());
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all.input_position[i] >= n)
      kept_ids.push_back(ES::Index(i));
  const ES::Point_tree kept_tree(all, kept_ids.begin(), kept_ids.end(), ConcurrencyTag());
  const bool has_planes = report.kept_size >= 3;
  const ES::Array<ES::Local_plane> planes =
    has_planes ? ES::kept_planes<ConcurrencyTag>(all, kept_ids, n, kept_tree) : ES::Array<ES::Local_plane>();

  // by input position, so that the sums below run in input order
  ES::Array<double> distance(n), plane_distance(n, 0.);
  ES::for_each_index<ConcurrencyTag>(
    all.size(),
    [&](std::size_t i) {
      const std::size_t position = all.input_position[i];
      if (position >= n)
        return;
      const ES::Index nearest = kept_tree.nearest_one(ES::Index(i));
      distance[position] = std::sqrt(ES::squared_distance(all.points[i], all.points[nearest]));
      if (has_planes)
        plane_distance[position] = ES::distance_to_plane(all.points[i], planes[all.input_position[nearest] - n]);
    },
    [](std::size_t) { return true; });

  double sum = 0., squares = 0.;
  for (std::size_t i = 0; i < n; ++i)
  {
    sum += distance[i];
    squares += plane_distance[i] * plane_distance[i];
    report.max_distance = (std::max)(report.max_distance, distance[i]);
  }
  const double unit = report.diagonal > 0. ? report.diagonal : 1.;
  report.mean_distance = sum / double(n) / unit;
  report.max_distance /= unit;
  report.point_to_plane =
    has_planes ? std::sqrt(squares / double(n)) / unit : std::numeric_limits<double>::quiet_NaN();
  return report;
}

} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_ENTROPY_SIMPLIFICATION_MEASURE_SIMPLIFICATION_QUALITY_H
