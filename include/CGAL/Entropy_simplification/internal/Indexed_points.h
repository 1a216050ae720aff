// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's working copy of a point range.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_POINTS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_POINTS_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/tags.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

using Index = std::uint32_t;
using Working_kernel = CGAL::Simple_cartesian<double>;
using Working_point = Working_kernel::Point_3;

// The points in double precision, in spatial (Hilbert) order so that
// neighbours are near each other in memory, each with its position in the
// input range. Every order the package defines breaks ties by that position,
// so results do not depend on the internal order.
struct Indexed_points
{
  std::vector<Working_point> points;
  std::vector<Index> input_position;

  std::size_t size() const { return points.size(); }
};

// 0, 1, ..., n - 1.
inline std::vector<Index> all_indices(std::size_t n)
{
  std::vector<Index> indices(n);
  for (std::size_t i = 0; i < n; ++i)
    indices[i] = Index(i);
  return indices;
}

// The squared distance every neighbour order of the package uses.
inline double squared_distance(const Working_point& a, const Working_point& b)
{
  const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
  return dx * dx + dy * dy + dz * dz;
}

// The largest coordinate magnitude the package accepts. Squared distances,
// and the products of the normal estimation's covariances, overflow doubles
// near 1e154; 1e150 leaves room for sums over 1000 neighbours.
constexpr double largest_coordinate = 1e150;

// The points of a range in input order, in double precision. Throws
// std::invalid_argument on a coordinate that is not finite or exceeds
// largest_coordinate: the Kd tree and every distance would be meaningless.
template <typename Iterator, typename PointMap>
std::vector<Working_point> copy_finite_points(Iterator first, Iterator beyond, PointMap point_map)
{
  auto in_range = [](double c) { return std::abs(c) <= largest_coordinate; }; // false for NaN
  std::vector<Working_point> points;
  for (Iterator it = first; it != beyond; ++it)
  {
    if (points.size() >= std::size_t((std::numeric_limits<Index>::max)()))
      throw std::invalid_argument("the package handles fewer than 2^32 - 1 points");
    const auto& p = get(point_map, *it);
    const Working_point q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if (!(in_range(q.x()) && in_range(q.y()) && in_range(q.z())))
      throw std::invalid_argument("point #" + std::to_string(points.size()) +
                                  " has a coordinate that is not finite or exceeds 1e150 in magnitude");
    points.push_back(q);
  }
  return points;
}

// Reorders points given in input order along a Hilbert curve.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Indexed_points sort_spatially(const std::vector<Working_point>& points_in_input_order)
{
  // The property map's key type is std::size_t, and spatial_sort wants it
  // to be the sorted value type.
  std::vector<std::size_t> order(points_in_input_order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  using Sort_traits =
    CGAL::Spatial_sort_traits_adapter_3<Working_kernel,
                                        CGAL::Pointer_property_map<Working_point>::const_type>;
  // spatial_sort shuffles with a fixed seed, so the order is reproducible.
  // Its parallel version makes the same splits, so the order is the same.
  CGAL::spatial_sort<ConcurrencyTag>(order.begin(), order.end(),
                                     Sort_traits(CGAL::make_property_map(points_in_input_order)));

  Indexed_points result;
  result.input_position.assign(order.begin(), order.end());
  result.points.reserve(points_in_input_order.size());
  for (Index i : result.input_position)
    result.points.push_back(points_in_input_order[i]);
  return result;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_POINTS_H
