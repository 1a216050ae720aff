// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The importance of every point: the value a mode of the simplification
// orders the points by, taken on the input before any removal.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_COMPUTE_ENTROPY_IMPORTANCE_H
#define CGAL_ENTROPY_SIMPLIFICATION_COMPUTE_ENTROPY_IMPORTANCE_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Distinct_points.h>
#include <CGAL/Entropy_simplification/internal/Elimination_field.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Paper_simplification.h>
#include <CGAL/Entropy_simplification/internal/named_parameters.h>
#include <CGAL/Entropy_simplification/internal/reference_plane.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>

namespace CGAL {

// ----------------------------------------------------------------------------
// Private section
// ----------------------------------------------------------------------------
/// \cond SKIP_IN_MANUAL
namespace Entropy_simplification {
namespace internal {

// The importance of each distinct point, in input order, as `options.mode`
// computes it before any removal; empty when the callback stopped it.
template <typename ConcurrencyTag>
Array<double> importance_of_distinct_points(Array<Working_point>&& points, unsigned int k,
                                                  const Options& options,
                                                  const std::function<bool(double)>& callback)
{
  const auto report = [&callback](double fraction) { return !callback || callback(fraction); };
  const Working_vector plane_normal =
    options.mode == Mode::paper ? reference_normal(options, points) : Working_vector(CGAL::NULL_VECTOR);
  const Indexed_points indexed = sort_spatially<ConcurrencyTag>(std::move(points));
  Array<double> by_index;
  if (options.mode == Mode::paper)
  {
    Paper_simplification state(indexed, k, options, plane_normal);
    if (!state.template initialize<ConcurrencyTag>(report))
      return {};
    for (Index i = 0; i < Index(indexed.size()); ++i)
      by_index.push_back(state.importance(i));
  }
  else
  {
    by_index = feature_strength_of_all<ConcurrencyTag>(indexed, k, options, report);
    if (by_index.empty())
      return {};
  }
  Array<double> importance(indexed.size());
  for (Index i = 0; i < Index(indexed.size()); ++i)
    importance[indexed.input_position[i]] = by_index[i];
  return importance;
}

} // namespace internal
} // namespace Entropy_simplification
/// \endcond

// ----------------------------------------------------------------------------
// Public section
// ----------------------------------------------------------------------------

/**
   \ingroup PkgEntropySimplificationRef

   Computes the importance of every point of a point set: the value by which
   a mode of `CGAL::entropy_simplify_point_set()` orders the points, taken on
   the whole input before any removal, on its distinct points as that
   function takes them.

   - <b>`Mode::paper`</b>: the entropy of normal angles of Eq. 5, in nats, in
     `[0, log(k + 1)]`: the value the method removes points by, the lowest
     first with `Removal_order::lowest_entropy_first` (the default), the
     highest first otherwise.
   - <b>`Mode::weighted_elimination` (the default)</b>: the feature strength,
     in `[0, 1]`: 0 where the normals of the point's neighbourhood vary no
     more than twice the cloud's own noise, 1 from ten times the noise, at
     the scale of `k` or at the coarse scale, whichever is greater. The
     point's weight in the distances the elimination keeps low grows with
     it, so that points of greater importance are kept denser, by up to
     `1 + Options::feature_weight`.

   A copy of a coincident point gets the importance of its first copy.

   \tparam ConcurrencyTag enables sequential versus parallel computation.
   Possible values are `Sequential_tag`, `Parallel_tag`, and
   `Parallel_if_available_tag`. The result does not depend on it.
   \tparam PointRange is a model of `ConstRange`. The value type of its
   iterator is the key type of the named parameter `point_map` and of
   `ImportanceMap`.
   \tparam ImportanceMap a model of `WritablePropertyMap` whose key type is
   the value type of the iterator of `PointRange` and whose value type is
   `double`, such as a `double` property map of a `CGAL::Point_set_3`, or
   `CGAL::Second_of_pair_property_map` on a range of `std::pair<Point_3,
   double>`

   \param points input point range
   \param k number of neighbours of each point, as for
   `CGAL::entropy_simplify_point_set()`
   \param importance_map receives the importance of each point
   \param np an optional sequence of \ref bgl_namedparameters "Named Parameters"
   among the ones listed below; any other is rejected at compile time
   \param options the package's options (`Entropy_simplification::Options`);
   this function reads `mode`, `normal_estimation` and, in `Mode::paper`,
   `reference_normal`

   \cgalNamedParamsBegin
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
       \cgalParamExtra{Called on the calling thread with the fraction of the work done.
                       When it returns `false`, the function stops and writes nothing.}
     \cgalParamNEnd
     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \return `true` when the importances were written; `false`, with nothing
   written, when the callback stopped the computation. An empty range writes
   nothing and returns `true`. The points are only read; the range is taken
   by non-`const` reference so that the map can write into its elements, as
   for `CGAL::pca_estimate_normals()`.

   \throw std::invalid_argument when a coordinate is not finite or exceeds
   1e150 in magnitude, the points span less than 1e-150 but more than 0, or
   two distinct points lie closer than about 1.5e-154 to each other;
   when `k` is out of range or the range has fewer than
   `k + 1` distinct points (as for `CGAL::entropy_simplify_point_set()`); in
   `Mode::paper`, when `Options::reference_normal` is null or not finite.
*/
template <typename ConcurrencyTag, typename PointRange, typename ImportanceMap,
          typename NamedParameters = parameters::Default_named_parameters>
bool compute_entropy_importance(PointRange& points, unsigned int k, ImportanceMap importance_map,
                                const NamedParameters& np = parameters::default_values(),
                                const Entropy_simplification::Options& options = Entropy_simplification::Options())
{
  namespace ES = Entropy_simplification::internal;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static_assert(ES::Uses_only_named_parameters<NamedParameters, internal_np::point_t, internal_np::callback_t,
                                               internal_np::geom_traits_t>::value,
                "compute_entropy_importance() reads only the named parameters point_map, callback and geom_traits");
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());

  const ES::First_touch_scope<ConcurrencyTag> first_touch;
  ES::Array<ES::Working_point> input = ES::working_points(points, np);
  const std::size_t n = input.size();
  if (n == 0)
    return true;
  ES::Distinct_points distinct = ES::collapse_duplicates<ConcurrencyTag>(std::move(input));
  ES::check_simplification_arguments(n, distinct.size(), k, n, options);

  const ES::Array<double> of_distinct =
    ES::importance_of_distinct_points<ConcurrencyTag>(std::move(distinct.points), k, options, callback);
  if (of_distinct.empty())
    return false;
  ES::Array<double> of_input(n);
  for (std::size_t d = 0; d < distinct.size(); ++d)
    of_input[distinct.input_position[d]] = of_distinct[d];
  for (std::size_t c = 0; c < distinct.copies.size(); ++c)
    of_input[distinct.copies[c]] = of_distinct[distinct.representative[c]];
  std::size_t position = 0;
  for (auto it = points.begin(); it != points.end(); ++it)
    put(importance_map, *it, of_input[position++]);
  return true;
}

} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_ENTROPY_SIMPLIFICATION_COMPUTE_ENTROPY_IMPORTANCE_H
