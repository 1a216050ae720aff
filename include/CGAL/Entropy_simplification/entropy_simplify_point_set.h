// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Progressive simplification of a point set by the local entropy of normal
// angles.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_ENTROPY_SIMPLIFY_POINT_SET_H
#define CGAL_ENTROPY_SIMPLIFICATION_ENTROPY_SIMPLIFY_POINT_SET_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Decremental_knn.h>
#include <CGAL/Entropy_simplification/internal/Distinct_points.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>
#include <CGAL/Entropy_simplification/internal/named_parameters.h>
#include <CGAL/Entropy_simplification/internal/order_by_removal.h>
#include <CGAL/Entropy_simplification/internal/simplify_points.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {

// ----------------------------------------------------------------------------
// Private section
// ----------------------------------------------------------------------------
/// \cond SKIP_IN_MANUAL
namespace Entropy_simplification {
namespace internal {

inline void check_simplification_arguments(std::size_t n, std::size_t distinct, unsigned int k,
                                           std::size_t target, const Options& options)
{
  if (k < minimum_k(options.normal_estimation) || k > Decremental_knn::largest_k)
    throw std::invalid_argument("k = " + std::to_string(k) + " is out of range: the normal estimation needs k in [" +
                                std::to_string(minimum_k(options.normal_estimation)) + ", " +
                                std::to_string(Decremental_knn::largest_k) + "]");
  if (distinct < std::size_t(k) + 1)
    throw std::invalid_argument("k = " + std::to_string(k) + " needs at least k + 1 distinct points; the range has " +
                                std::to_string(distinct) + " (of " + std::to_string(n) + " points)");
  if (options.mode == Mode::paper && target < std::size_t(k) + 1)
    throw std::invalid_argument("the paper's mode must keep at least k + 1 = " + std::to_string(k + 1) +
                                " points so that every point keeps k neighbours; " + std::to_string(target) +
                                " were asked");
  if (!(options.feature_weight >= 0. && options.feature_weight <= Options::largest_feature_weight))
    throw std::invalid_argument("Options::feature_weight must lie in [0, 100]");
}

} // namespace internal
} // namespace Entropy_simplification
/// \endcond

// ----------------------------------------------------------------------------
// Public section
// ----------------------------------------------------------------------------

/**
   \ingroup PkgEntropySimplificationRef

   Simplifies a point set down to exactly the requested number of points,
   guided by the local entropy of normals, after "A New Progressive
   Simplification Method for Point Cloud Using Local Entropy of Normal Angle"
   (J. Indian Soc. Remote Sens. 46(4), 2018).

   This function modifies the order of the input points so as to pack all
   kept points first, in their input order, and returns an iterator over the
   first point to remove (see erase-remove idiom). The removed points follow
   in reverse order of removal, the last removed first, so that the first `m`
   points, for any `m` above the number kept, are a simplification to `m`
   points (in `Mode::paper`, exactly the one a call asking for `m` points
   gives). Points are only moved: coordinates and other attributes are never
   altered.

   Coincident points (equal as doubles, `-0.0` equal to `0.0`) are first
   collapsed to their first copy in input order: both modes run on the
   distinct points, and the other copies are removed before any of them.
   Copies are kept only when more points are asked for than there are
   distinct points, and then the earliest copies in input order. The paper
   is silent on coincident points; this is the package's one deviation from
   it in `Mode::paper`. Then, with `N(p)` the `k` nearest neighbours of `p`
   among the distinct points (`p` excluded, ties broken by
   input position), and the normal of `p` estimated on `p` and `N(p)`, `k + 1`
   points, as `CGAL::pca_estimate_normals()` does (Eq. 1-2;
   `Options::normal_estimation` selects jet fitting instead), the two methods
   of `Options::mode` are:

   <b>`Mode::weighted_elimination` (the default).</b> A greedy coverage
   elimination: every input point follows its nearest and next nearest kept
   point, and the kept points are removed, in rounds, by least cost, the
   increase of the weighted sum of the distances from the input points to
   their nearest kept point that a removal alone would cause. Each round
   removes every kept point whose cost is below that of each kept point it
   shares an input point with (as nearest and next), among the tenth of
   least cost (ties: the lowest scrambled input position), until the
   target. An input point weighs `(1 + w s)^e`, `s` its feature strength
   and `w` `Options::feature_weight`, lowered where features cover much of
   the area, so that features keep up to about `1 + w` times the density of
   flat regions: `e` is 1.1 while more than 35% of the distinct points are
   kept, 1.35 while more than 20%, and 1.6 below, as a weight buys a
   greater density where each kept point stands for fewer input points;
   while more than 35% are kept, `(1 + w s^2)^e`, so that weak features
   take fewer points from the flat regions there.
   The feature strength is the variation of the normals of `p` and `N(p)`, the entropy of the eigenvalues of their
   orientation tensor, independent of their orientation and of any
   reference plane, measured against the cloud's own noise (its median), at
   the scale of `k` and at a coarser scale. Where the input's density
   varies, the kept density follows it to about the power 2/3, the density
   that minimises such a sum. Two iterations of a relaxation restricted to the
   input points end it: each kept point gives way to the median of its
   Voronoi cell among the input points, the member whose distances to the
   others sum least among the four nearest the cell's centroid, unless that
   would take a cell's farthest member farther than the members nearest the
   centroids keep any. Flat regions thin evenly, without holes; the user
   manual and its design notes give the reasoning and the measurements.

   <b>`Mode::paper`, the paper's method,</b> with `N(p)` taken among the
   points still present:
   - a reference plane is fitted to all the distinct points once (Eq. 3; or
     given in `Options::reference_normal`);
   - the normal angle `theta_p` of `p` is the angle between its normal and the
     reference plane, in `[0, pi/2]` (Eq. 4); it is 0 for a point without
     normal (a jet fit can degenerate);
   - the importance of `p` is the entropy, in nats, of the angles of `p` and
     `N(p)` normalised by their sum (Eq. 5), with `0 log 0 = 0` and an
     importance of 0 when all these angles are 0;
   - the point of least importance in the order of `Options::removal_order`
     (ties broken by input position) is removed, and the neighbourhoods,
     normals and importances it changed are updated, until the target count
     is reached.
   After every removal, every remaining point's neighbourhood, normal and
   importance are exactly what a computation from scratch on the remaining
   points would give. The paper only says to update the normals of the
   removed point's "first ring" and the importances of its "second ring";
   this contract is stricter and testable. The user manual documents each of
   these choices and what they measure: taken literally, this method leaves
   holes.

   \tparam ConcurrencyTag enables sequential versus parallel estimation and
   neighbour searches. Possible values are `Sequential_tag`, `Parallel_tag`,
   and `Parallel_if_available_tag`. The default mode's removals also run in
   parallel rounds; those of `Mode::paper` are sequential. The result does not
   depend on the tag.
   \tparam PointRange is a model of `Range`. The value type of its iterator is
   the key type of the named parameter `point_map`; its elements must be
   move-constructible and move-assignable.

   \param points input point range
   \param k number of neighbours of each point, for its normal and its
   importance
   \param np a sequence of \ref bgl_namedparameters "Named Parameters" among
   the ones listed below. Exactly one of `number_of_output_points` and
   `select_percentage` must be given. Any other named parameter is rejected at
   compile time rather than silently ignored.
   \param options the package's options (`Entropy_simplification::Options`)

   \cgalNamedParamsBegin
     \cgalParamNBegin{number_of_output_points}
       \cgalParamDescription{the number of points to keep; a number above the
       size of the range keeps every point}
       \cgalParamType{an integral type}
       \cgalParamDefault{none: give this or `select_percentage`}
       \cgalParamExtra{Must be positive; in `Mode::paper`, at least `k + 1`.}
     \cgalParamNEnd

     \cgalParamNBegin{select_percentage}
       \cgalParamDescription{the percentage of the points to keep, in `(0, 100]`.
       The number kept is `ceil(n * select_percentage / 100)` for `n` points,
       where a product within a relative `1e-9` of an integer counts as that
       integer: 10% of 182,191 points is 18,220 points, as in the paper, and 7%
       of 100 points is 7 points. It is at least 1.}
       \cgalParamType{double}
       \cgalParamDefault{none: give this or `number_of_output_points`}
       \cgalParamExtra{In `Mode::paper`, the resulting number must be at least `k + 1`.}
     \cgalParamNEnd

     \cgalParamNBegin{point_map}
       \cgalParamDescription{a property map associating points to the elements of the point set `points`}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
       \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`, or the point
                         map of a `CGAL::Point_set_3`}
     \cgalParamNEnd

     \cgalParamNBegin{normal_map}
       \cgalParamDescription{a property map that receives the final unit normal of every
       kept point (the null vector where it is undefined): in `Mode::paper`,
       estimated on its neighbours among the kept points; in the default mode,
       on its neighbours in the input, a better estimate. A kept copy of a point
       receives the normal of its first copy. Nothing else is written: without this
       parameter, the points' normals, such as those of a `CGAL::Point_set_3`,
       are left untouched.}
       \cgalParamType{a model of `WritablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Vector_3`}
       \cgalParamDefault{none: no normal is written}
     \cgalParamNEnd

     \cgalParamNBegin{callback}
       \cgalParamDescription{a mechanism to get feedback on the advancement of the algorithm
                             while it is running and to interrupt it if needed}
       \cgalParamType{an instance of `std::function<bool(double)>`.}
       \cgalParamDefault{unused}
       \cgalParamExtra{It is called on the calling thread with the fraction of the work
                       done, in `[0, 1]`: the initial estimation counts for the first
                       quarter, then the removals, about a thousand calls in all. When it
                       returns `false`, the algorithm stops: the points removed so far
                       follow the kept ones, in reverse order of removal as always, and
                       the points still present are kept (everything is kept when it
                       stops during the initial estimation). In `Mode::paper`, that is
                       exactly what a call asking for that number of points gives. In
                       the default mode, whose relocation depends on the target, it is
                       the state of the elimination at that moment, without the final
                       relocation and coverage swaps.}
     \cgalParamNEnd

     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \return iterator over the first point to remove; `points.end()` for an
   empty range, or when nothing is removed.

   \throw std::invalid_argument (in every build type, before any point is
   moved) when a coordinate is not finite or exceeds 1e150 in magnitude (squared
   distances would overflow); when the points span less than 1e-150 along
   every axis but do not all coincide, or when two distinct points lie
   closer than about 1.5e-154 to each other, whatever the extent of the
   cloud (squared distances would underflow); when `k` is below 2 (below 5 with
   jet fitting) or above 1000; when the range has fewer than `k + 1` distinct
   points;
   when `select_percentage` is outside `(0, 100]` or `number_of_output_points`
   is not positive; when `Options::feature_weight` is negative or not finite;
   in `Mode::paper`, when fewer than `k + 1` points would be kept, or when
   `Options::reference_normal` is null or not finite.

   Coincident points are valid input and cost no more than the search that
   finds them, however many copies there are. Points that differ by any
   amount, however small, are distinct. In `Mode::paper`, a planar cloud
   gives every point the same importance, so points are removed in input
   order. A collinear cloud gives an arbitrary but deterministic result.
*/
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
typename PointRange::iterator
entropy_simplify_point_set(PointRange& points, unsigned int k,
                           const NamedParameters& np = parameters::default_values(),
                           const Entropy_simplification::Options& options = Entropy_simplification::Options())
{
  namespace ES = Entropy_simplification::internal;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static_assert(ES::Uses_only_named_parameters<NamedParameters, internal_np::point_t, internal_np::normal_t,
                                               internal_np::callback_t, internal_np::geom_traits_t,
                                               internal_np::number_of_output_points_t,
                                               internal_np::select_percentage_t>::value,
                "entropy_simplify_point_set() reads only the named parameters number_of_output_points, "
                "select_percentage, point_map, normal_map, callback and geom_traits");

  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Kernel;
  constexpr bool has_normal_map = !parameters::is_default_parameter<NamedParameters, internal_np::normal_t>::value;
  // by value: get_parameter returns a temporary
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());

  const ES::First_touch_scope<ConcurrencyTag> first_touch;
  ES::Array<ES::Working_point> input = ES::working_points(points, np);
  const std::size_t n = input.size();
  if (n == 0)
    return points.end();
  const std::size_t target = ES::requested_output_size(n, np);
  ES::Distinct_points distinct = ES::collapse_duplicates<ConcurrencyTag>(std::move(input));
  ES::check_simplification_arguments(n, distinct.size(), k, target, options);
  if (target == n && !has_normal_map)
    return points.end();

  // the kept points' normals wait for the run to end, so that the iterators
  // to the range are not held at its peak of memory
  ES::Array<std::pair<ES::Index, ES::Working_vector> > normals;
  const ES::Array<ES::Index> removed =
    ES::simplify_points<ConcurrencyTag>(
      std::move(distinct), k, target, ES::Run_extent::to_target, options, callback, has_normal_map,
      [&](ES::Index position, const ES::Working_vector& n) { normals.emplace_back(position, n); })
      .value_or(ES::Array<ES::Index>());

  const auto at = ES::iterators_of(points);
  if constexpr (has_normal_map)
    for (const auto& [position, n] : normals)
      put(get_parameter(np, internal_np::normal_map), *at[position],
          typename Kernel::Vector_3(typename Kernel::FT(n.x()), typename Kernel::FT(n.y()),
                                    typename Kernel::FT(n.z())));
  const std::size_t kept = ES::order_by_removal<ConcurrencyTag>(at, removed);
  return kept == at.size() ? points.end() : at[kept];
}

} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_ENTROPY_SIMPLIFICATION_ENTROPY_SIMPLIFY_POINT_SET_H
