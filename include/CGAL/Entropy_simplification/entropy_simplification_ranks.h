// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Levels of detail from one run: the rank of every point, so that any prefix
// of the points ordered by rank is a simplification.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_ENTROPY_SIMPLIFICATION_RANKS_H
#define CGAL_ENTROPY_SIMPLIFICATION_ENTROPY_SIMPLIFICATION_RANKS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Distinct_points.h>
#include <CGAL/Entropy_simplification/internal/named_parameters.h>
#include <CGAL/Entropy_simplification/internal/simplify_points.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>

namespace CGAL {

// ----------------------------------------------------------------------------
// Private section
// ----------------------------------------------------------------------------
/// \cond SKIP_IN_MANUAL
namespace Entropy_simplification {
namespace internal {

// The ranks of n points from the removals of a run through the kept points:
// the points no removal took first, in input order, then the removed ones,
// the last removed first.
inline Array<std::size_t> ranks_from_removals(std::size_t n, const Array<Index>& removed)
{
  constexpr std::size_t unranked = (std::numeric_limits<std::size_t>::max)();
  Array<std::size_t> rank(n, unranked);
  for (std::size_t j = 0; j < removed.size(); ++j)
    rank[removed[j]] = n - 1 - j;
  std::size_t next = 0;
  for (std::size_t& r : rank)
    if (r == unranked)
      r = next++;
  return rank;
}

// The level whose prefix is exactly a simplification's result: the one of
// the named parameters, or all the points.
template <typename NamedParameters>
std::size_t exact_level(std::size_t n, const NamedParameters& np)
{
  constexpr bool has_level =
    !parameters::is_default_parameter<NamedParameters, CGAL::internal_np::number_of_output_points_t>::value ||
    !parameters::is_default_parameter<NamedParameters, CGAL::internal_np::select_percentage_t>::value;
  if constexpr (has_level)
    return requested_output_size(n, np);
  else
    return n;
}

} // namespace internal
} // namespace Entropy_simplification
/// \endcond

// ----------------------------------------------------------------------------
// Public section
// ----------------------------------------------------------------------------

/**
   \ingroup PkgEntropySimplificationRef

   Computes the rank of every point of a point set, for levels of detail from
   one run: ordered by rank, the first `m` points are a simplification to `m`
   points, for every `m`. Rank 0 is the point kept longest.

   <b>`Mode::paper`.</b> The ranks are the reverse of the order of removal of
   one run of `CGAL::entropy_simplify_point_set()` down to `k + 1` points, and
   those `k + 1` points, which the method never removes, take ranks `0` to
   `k` in input order. The removals being exactly progressive, the first `m`
   points by rank are exactly the points a call of
   `CGAL::entropy_simplify_point_set()` asking for `m` points keeps, for every
   `m >= k + 1`. The level named parameters are not needed.

   <b>`Mode::weighted_elimination` (the default).</b> Its relocation
   depends on the target, so that no order has every prefix equal to a
   direct call's result. The ranks make one level exact, the level `L`
   given by `number_of_output_points` or `select_percentage` (all the points
   by default), and relocate the round fractions below it:
   - the first `L` points by rank are exactly the points a call of
     `CGAL::entropy_simplify_point_set()` asking for `L` points keeps;
   - the points that call removes follow, the last removed first: a longer
     prefix is the state of its elimination when that many points remained,
     before the relocation and the coverage swaps that end the call;
   - the `L` kept points are ordered by going on with the elimination among
     them down to one point, every input point following its nearest and
     next kept points among them, in stages that end at the level
     boundaries:
     50, 20, 10, 5, 2, 1, 0.5, 0.2, 0.1%, ... of the distinct points,
     rounded up. At each boundary, each input point belongs to a cell
     with one present point: at first, the kept point nearest it; a point
     the stage removed brings its cell into that of its nearest present
     neighbour. Each cell's point is then replaced by the cell's median
     among it and the cell's points that stage removed (the one whose
     distances to the cell's input points sum least). Down to the
     boundary of 1%, each input point then joins the cell of its nearest
     present point, and each cell's point is replaced once more by its
     median among it and the stage's removed points of the cell: two
     steps, as a direct call's relocation takes, though a direct call may
     choose any input point of a cell. So the prefix stands for the input
     points nearest it, as a direct call's relocation makes its result do,
     while the prefixes stay nested;
   - once at most 1% of the distinct points (rounded up) are present, from
     the start when `L` is that small, each present point stands for the
     input points nearest it: it weighs as much as they do together, and
     it is as far from a point at distance `d` as `sqrt(d^2 + s^2)`, where
     `s` is their mean distance to it, as if they were spread around it.
     Only these points follow the present points from then on, so that
     the stages below 1% cost little; the cells of the boundaries still
     hold every input point.

   Without a level, every boundary is thus relocated: on the benchmark's
   inputs, a prefix's mean distance to the input is at most 1.045 times
   that of a direct call to its size at 1, 5, 10, 20 and 50% of the
   points, and its point-to-plane error at most 1.053 times (radar at 5%,
   a noisy scan whose ratios move by several hundredths when a handful of
   points change; the user manual gives the figures); at 0.5% and 0.1%, where the kept
   points stand for the input points, the mean distance is up to 1.049 and
   1.064 times. With a level, the prefixes longer than `L` are not
   relocated, and are up to 1.089 times worse. The whole order costs 1.29
   to 1.34 times a direct call to 1% of the points without a level, and
   1.03 to 1.12 times with the level at 1% (medians on 100,000 and
   1,000,000 points, with one thread and with two, in the benchmark's last
   run, on a shared machine whose runs vary by several hundredths: 1.03 to
   1.09 with the level in the run before).

   Coincident points are ranked last: their first copy in input order takes
   part in the run, and the other copies take the last ranks, the earliest
   copy first, as `CGAL::entropy_simplify_point_set()` removes them.

   \tparam ConcurrencyTag enables sequential versus parallel computation.
   Possible values are `Sequential_tag`, `Parallel_tag`, and
   `Parallel_if_available_tag`. The ranks do not depend on it.
   \tparam PointRange is a model of `ConstRange`. The value type of its
   iterator is the key type of the named parameter `point_map`.
   \tparam OutputIterator an output iterator accepting `std::size_t`

   \param points input point range
   \param k number of neighbours of each point, as for
   `CGAL::entropy_simplify_point_set()`
   \param ranks receives the rank of each point, in `[0, n)`, in the order of
   the range: the ranks of `n` points are a permutation of `0, ..., n - 1`
   \param np an optional sequence of \ref bgl_namedparameters "Named Parameters"
   among the ones listed below; any other is rejected at compile time
   \param options the package's options (`Entropy_simplification::Options`)

   \cgalNamedParamsBegin
     \cgalParamNBegin{number_of_output_points}
       \cgalParamDescription{the level `L` whose prefix is exactly a direct call's
       result, in the default mode}
       \cgalParamType{an integral type}
       \cgalParamDefault{all the points; give at most one of this and `select_percentage`}
       \cgalParamExtra{Must be positive. Read but without effect in `Mode::paper`.}
     \cgalParamNEnd
     \cgalParamNBegin{select_percentage}
       \cgalParamDescription{the level `L` as a percentage of the points, rounded
       as `CGAL::entropy_simplify_point_set()` rounds it}
       \cgalParamType{double}
       \cgalParamDefault{unused}
       \cgalParamExtra{Must lie in `(0, 100]`.}
     \cgalParamNEnd
     \cgalParamNBegin{point_map}
       \cgalParamDescription{a property map associating points to the elements of the point set `points`}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
       \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`, or the point
                         map of a `CGAL::Point_set_3`}
     \cgalParamNEnd
     \cgalParamNBegin{callback}
       \cgalParamDescription{a mechanism to get feedback on the advancement of the algorithm
                             while it is running and to interrupt it if needed}
       \cgalParamType{an instance of `std::function<bool(double)>`.}
       \cgalParamDefault{unused}
       \cgalParamExtra{Called on the calling thread with the fraction of the work done,
                       as by `CGAL::entropy_simplify_point_set()`; with a level,
                       with 1 while the default mode orders the kept points. When it returns
                       `false`, the function stops and writes no rank.}
     \cgalParamNEnd
     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \return `true` when the ranks were written; `false`, with nothing written,
   when the callback stopped the computation. An empty range writes nothing
   and returns `true`.

   \throw std::invalid_argument for the input and options that
   `CGAL::entropy_simplify_point_set()` rejects, except that `Mode::paper`
   accepts any level.
*/
template <typename ConcurrencyTag, typename PointRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
bool entropy_simplification_ranks(const PointRange& points, unsigned int k, OutputIterator ranks,
                                  const NamedParameters& np = parameters::default_values(),
                                  const Entropy_simplification::Options& options =
                                    Entropy_simplification::Options())
{
  namespace ES = Entropy_simplification::internal;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static_assert(ES::Uses_only_named_parameters<NamedParameters, internal_np::point_t, internal_np::callback_t,
                                               internal_np::geom_traits_t, internal_np::number_of_output_points_t,
                                               internal_np::select_percentage_t>::value,
                "entropy_simplification_ranks() reads only the named parameters number_of_output_points, "
                "select_percentage, point_map, callback and geom_traits");
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());

  const ES::First_touch_scope<ConcurrencyTag> first_touch;
  ES::Array<ES::Working_point> input = ES::working_points(points, np);
  const std::size_t n = input.size();
  if (n == 0)
    return true;
  const std::size_t level = ES::exact_level(n, np);
  ES::Distinct_points distinct = ES::collapse_duplicates<ConcurrencyTag>(std::move(input));
  const bool paper = options.mode == Entropy_simplification::Mode::paper;
  ES::check_simplification_arguments(n, distinct.size(), k, paper ? (std::max)(level, std::size_t(k) + 1) : level,
                                     options);

  const std::optional<ES::Array<ES::Index> > removed = ES::simplify_points<ConcurrencyTag>(
    std::move(distinct), k, level, ES::Run_extent::through_the_kept, options, callback, false,
    [](ES::Index, const ES::Working_vector&) {});
  if (!removed)
    return false;
  for (std::size_t r : ES::ranks_from_removals(n, *removed))
    *ranks++ = r;
  return true;
}

} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_ENTROPY_SIMPLIFICATION_ENTROPY_SIMPLIFICATION_RANKS_H
