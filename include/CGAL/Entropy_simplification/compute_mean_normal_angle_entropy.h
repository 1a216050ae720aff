// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's accuracy indicator (Eq. 6-7): the mean entropy of normal angles.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_COMPUTE_MEAN_NORMAL_ANGLE_ENTROPY_H
#define CGAL_ENTROPY_SIMPLIFICATION_COMPUTE_MEAN_NORMAL_ANGLE_ENTROPY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Distinct_points.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Paper_simplification.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>
#include <CGAL/Entropy_simplification/internal/named_parameters.h>
#include <CGAL/Entropy_simplification/internal/reference_plane.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {

/**
   \ingroup PkgEntropySimplificationRef

   Computes the paper's accuracy indicator of a (simplified) point set: the
   mean, over its points, of the entropy in bits of the normal angles of each
   point and its `k` nearest neighbours (Eq. 6-7).

   Everything is computed on the given points alone, exactly as
   `CGAL::entropy_simplify_point_set()` computes the importance of a point
   before any removal (same neighbourhoods, normals, angles and conventions),
   converted from nats to bits. Coincident points count in the mean, each
   with its `k` nearest neighbours, which may be its copies; past the first
   `k + 1` copies of a point, a copy has the importance of the first, and no
   search looks at it. The paper does not say which reference plane the
   angles of Eq. 6 use: by default the plane is fitted to the given points;
   to compare several simplifications of one input, pass the normal of the
   input's plane in `Options::reference_normal` (it is the normal of the plane
   `CGAL::linear_least_squares_fitting_3()` fits to the input).

   The paper reads a higher value as a better simplification. The indicator is
   largest, `log2(k + 1)`, where the angles of a neighbourhood are equal, so
   it rewards removing the points whose neighbourhoods have unequal angles,
   which is what `Removal_order::lowest_entropy_first` does by construction;
   the user manual shows what it measures.

   \tparam ConcurrencyTag enables sequential versus parallel computation.
   Possible values are `Sequential_tag`, `Parallel_tag`, and
   `Parallel_if_available_tag`. The result does not depend on it.
   \tparam PointRange is a model of `ConstRange`. The value type of its
   iterator is the key type of the named parameter `point_map`.

   \param points input point range
   \param k number of neighbours of each point
   \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among
   the ones listed below; any other is rejected at compile time
   \param options the package's options; this function reads
   `normal_estimation` and `reference_normal`

   \cgalNamedParamsBegin
     \cgalParamNBegin{point_map}
       \cgalParamDescription{a property map associating points to the elements of the point set `points`}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
       \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`, or the point
                         map of a `CGAL::Point_set_3`}
     \cgalParamNEnd

     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \return the mean entropy in bits, in `[0, log2(k + 1)]` up to rounding

   \throw std::invalid_argument when a coordinate is not finite or exceeds 1e150
   in magnitude, when the points span less than 1e-150 but more than 0, when
   two distinct points lie closer than about 1.5e-154 to each other (coincident
   points are accepted), when `k` is out of range (as for
   `CGAL::entropy_simplify_point_set()`), when the range
   has fewer than `k + 1` points, or when `Options::reference_normal` is null
   or not finite.
*/
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
double compute_mean_normal_angle_entropy(const PointRange& points, unsigned int k,
                                         const NamedParameters& np = parameters::default_values(),
                                         const Entropy_simplification::Options& options =
                                           Entropy_simplification::Options())
{
  namespace ES = Entropy_simplification::internal;
  static_assert(ES::Uses_only_named_parameters<NamedParameters, internal_np::point_t,
                                               internal_np::geom_traits_t>::value,
                "compute_mean_normal_angle_entropy() reads only the named parameters point_map and geom_traits");

  const ES::First_touch_scope<ConcurrencyTag> first_touch;
  ES::Array<ES::Working_point> input = ES::working_points(points, np);
  if (k < ES::minimum_k(options.normal_estimation) || input.size() < std::size_t(k) + 1)
    throw std::invalid_argument("compute_mean_normal_angle_entropy: k = " + std::to_string(k) +
                                " is too small for the normal estimation or too large for " +
                                std::to_string(input.size()) + " points");

  const std::size_t n = input.size();
  const ES::Working_vector reference = ES::reference_normal(options, input);
  // Copies count in the mean, but past the first k + 1 of a point they are
  // no point's neighbours and repeat the first's importance.
  ES::Limited_copies limited = ES::limit_copies<ConcurrencyTag>(std::move(input), std::size_t(k) + 1);
  const ES::Indexed_points indexed = ES::sort_spatially<ConcurrencyTag>(std::move(limited.points));
  ES::Paper_simplification state(indexed, k, options, reference);
  state.template initialize<ConcurrencyTag>([](double) { return true; });

  ES::Array<double> importance(indexed.size());
  for (ES::Index i = 0; i < ES::Index(indexed.size()); ++i)
    importance[indexed.input_position[i]] = state.importance(i);
  // Summed in input order, so that the result does not depend on the
  // package's internal order.
  double sum = 0.;
  for (std::size_t i = 0; i < n; ++i)
    sum += importance[limited.stand_in[i]];
  return sum / double(n) / std::log(2.);
}

} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_ENTROPY_SIMPLIFICATION_COMPUTE_MEAN_NORMAL_ANGLE_ENTROPY_H
