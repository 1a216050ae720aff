// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks on the named parameters a function of the package receives, and the
// rule that turns them into a number of output points.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// True when every named parameter of the chain `NP` carries one of the tags
// `Allowed...`. CGAL ignores named parameters a function does not read; the
// package rejects them at compile time instead, so that a parameter meant for
// another function is never silently dropped.
template <typename NP, typename... Allowed>
struct Uses_only_named_parameters;

template <typename... Allowed>
struct Uses_only_named_parameters<CGAL::internal_np::No_property, Allowed...>
  : std::true_type
{};

template <typename T, typename Tag, typename Base, typename... Allowed>
struct Uses_only_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>, Allowed...>
  : std::integral_constant<bool,
      (std::is_same<Tag, CGAL::internal_np::all_default_t>::value || ... ||
       std::is_same<Tag, Allowed>::value) &&
      Uses_only_named_parameters<Base, Allowed...>::value>
{};

// ceil(n * percentage / 100), where a product within a relative 1e-9 of an
// integer counts as that integer: 7% of 100 points is 7 points although
// 100 * 7.0 / 100 is not exactly 7 in binary. A positive percentage keeps at
// least one point, however small the product.
inline std::size_t kept_count_from_percentage(std::size_t n, double percentage)
{
  if (!(percentage > 0. && percentage <= 100.))
    throw std::invalid_argument("select_percentage must lie in (0, 100], got " +
                                std::to_string(percentage));
  const double exact = double(n) * percentage / 100.;
  const double nearest = std::round(exact);
  const std::size_t count = std::abs(exact - nearest) <= 1e-9 * (std::max)(1., exact)
                              ? std::size_t(nearest) : std::size_t(std::ceil(exact));
  return n == 0 ? 0 : (std::max)(count, std::size_t(1));
}

// The number of points to keep, from exactly one of `number_of_output_points`
// and `select_percentage`; a count above `n` keeps every point.
template <typename NamedParameters>
std::size_t requested_output_size(std::size_t n, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  constexpr bool has_count =
    !is_default_parameter<NamedParameters, CGAL::internal_np::number_of_output_points_t>::value;
  constexpr bool has_percentage =
    !is_default_parameter<NamedParameters, CGAL::internal_np::select_percentage_t>::value;
  static_assert(has_count != has_percentage,
                "give exactly one of the named parameters number_of_output_points and select_percentage");

  if constexpr (has_count)
  {
    const auto count = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_output_points), 0);
    if (count <= 0)
      throw std::invalid_argument("number_of_output_points must be positive");
    return (std::min)(n, std::size_t(count));
  }
  else
  {
    const double percentage =
      choose_parameter(get_parameter(np, CGAL::internal_np::select_percentage), 0.);
    return kept_count_from_percentage(n, percentage);
  }
}

// The points of a range, through the point map of the named parameters, in
// input order and double precision (see copy_finite_points).
template <typename PointRange, typename NamedParameters>
Array<Working_point> working_points(const PointRange& points, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  return copy_finite_points(points.begin(), points.end(), NP_helper::get_const_point_map(points, np));
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NAMED_PARAMETERS_H
