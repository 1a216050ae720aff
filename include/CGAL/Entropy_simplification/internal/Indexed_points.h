// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's working copy of a point range.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_POINTS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_POINTS_H

#include <CGAL/Entropy_simplification/internal/Array.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

using Index = std::uint32_t;
// No point: the site of a point that has no present point, for example.
constexpr Index none_index = Index(-1);
using Working_kernel = CGAL::Simple_cartesian<double>;
using Working_point = Working_kernel::Point_3;

// The points in double precision, in kd order (see sort_spatially) so that
// neighbours are near each other in memory, each with its position in the
// input range. Every neighbour and removal order the package defines breaks
// ties by that position, so none depends on the internal order; the default
// mode's coarse points and budget do (see Elimination_field.h).
struct Indexed_points
{
  Array<Working_point> points;
  Array<Index> input_position;

  std::size_t size() const { return points.size(); }
};

// 0, 1, ..., n - 1.
inline Array<Index> all_indices(std::size_t n)
{
  Array<Index> indices(n);
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

// The smallest extent, the largest side of the bounding box, the package
// accepts for a cloud of more than one position. Below about 1e-154, the
// squared distances between the points underflow to subnormal numbers and
// then to 0, and every order the package defines would be meaningless.
constexpr double smallest_extent = 1e-150;

// Whether the points `a` and `b`, at the squared distance `squared_distance`,
// are distinct but too near to be told apart: closer than about 1.5e-154,
// their squared distance underflows to a subnormal number or to 0, and every
// order the package defines would be meaningless among them. The extent of
// a cloud (smallest_extent) cannot rule this out where a cloud of normal
// extent holds such a cluster.
inline bool too_near_to_tell_apart(const Working_point& a, const Working_point& b, double squared_distance)
{
  return squared_distance < (std::numeric_limits<double>::min)() && a != b;
}

// What a function that found such points throws.
inline std::invalid_argument points_too_near_to_tell_apart()
{
  return std::invalid_argument("two distinct points lie closer than about 1.5e-154 to each other: their squared "
                               "distance underflows, and no neighbour order can tell them apart");
}

// The points of a range in input order, in double precision. Throws
// std::invalid_argument on a coordinate that is not finite or exceeds
// largest_coordinate, or on a nonzero extent below smallest_extent: the Kd
// tree and every distance would be meaningless.
template <typename Iterator, typename PointMap>
Array<Working_point> copy_finite_points(Iterator first, Iterator beyond, PointMap point_map)
{
  auto in_range = [](double c) { return std::abs(c) <= largest_coordinate; }; // false for NaN
  Array<Working_point> points;
  // reserved, so that a large range is copied without growing by doubling
  if constexpr (std::is_base_of<std::forward_iterator_tag,
                                typename std::iterator_traits<Iterator>::iterator_category>::value)
    points.reserve(std::size_t(std::distance(first, beyond)));
  double low[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, high[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (Iterator it = first; it != beyond; ++it)
  {
    if (points.size() >= std::size_t((std::numeric_limits<Index>::max)()))
      throw std::invalid_argument("the package handles fewer than 2^32 - 1 points");
    const auto& p = get(point_map, *it);
    const Working_point q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if (!(in_range(q.x()) && in_range(q.y()) && in_range(q.z())))
      throw std::invalid_argument("point #" + std::to_string(points.size()) +
                                  " has a coordinate that is not finite or exceeds 1e150 in magnitude");
    for (int d = 0; d < 3; ++d)
    {
      low[d] = (std::min)(low[d], q.cartesian(d));
      high[d] = (std::max)(high[d], q.cartesian(d));
    }
    points.push_back(q);
  }
  double extent = 0.;
  for (int d = 0; d < 3 && !points.empty(); ++d)
    extent = (std::max)(extent, high[d] - low[d]);
  if (extent > 0. && extent < smallest_extent)
  {
    char span[32];
    std::snprintf(span, sizeof span, "%.3g", extent);
    throw std::invalid_argument(std::string("the points span at most ") + span + " along any axis, which is not 0 "
                                "but below 1e-150: the squared distances between them would underflow");
  }
  return points;
}

// The indices of the points in input order.
inline Array<Index> indices_by_input_position(const Indexed_points& points)
{
  Array<Index> by_input(points.size());
  for (Index i = 0; i < Index(points.size()); ++i)
    by_input[points.input_position[i]] = i;
  return by_input;
}

// A point with its input position.
using Positioned_point = std::pair<Working_point, Index>;

// The side along which points spread widest: 0, 1 or 2 for x, y or z, the
// first of equal sides.
inline int widest_side(const Positioned_point* first, const Positioned_point* beyond)
{
  double low[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, high[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const Positioned_point* p = first; p != beyond; ++p)
    for (int d = 0; d < 3; ++d)
    {
      low[d] = (std::min)(low[d], p->first.cartesian(d));
      high[d] = (std::max)(high[d], p->first.cartesian(d));
    }
  int side = 0;
  for (int d = 1; d < 3; ++d)
    if (high[d] - low[d] > high[side] - low[side])
      side = d;
  return side;
}

// Puts points in kd order: the lower half first, split along the widest
// side, ties by input position so that the halves are unique, each half in
// kd order in turn, down to single points. The halves are independent, so
// the parallel sort gives the sequential one's order.
template <typename ConcurrencyTag>
void sort_in_kd_order(Positioned_point* first, Positioned_point* beyond)
{
  if (beyond - first < 2)
    return;
  const int side = widest_side(first, beyond);
  Positioned_point* middle = first + (beyond - first) / 2;
  std::nth_element(first, middle, beyond, [side](const Positioned_point& a, const Positioned_point& b) {
    const double ca = a.first.cartesian(side), cb = b.first.cartesian(side);
    return ca < cb || (ca == cb && a.second < b.second);
  });
#ifdef CGAL_LINKED_WITH_TBB
  if (std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && beyond - first > (1 << 16))
  {
    tbb::parallel_invoke([&] { sort_in_kd_order<ConcurrencyTag>(first, middle); },
                         [&] { sort_in_kd_order<ConcurrencyTag>(middle, beyond); });
    return;
  }
#endif
  sort_in_kd_order<ConcurrencyTag>(first, middle);
  sort_in_kd_order<ConcurrencyTag>(middle, beyond);
}

// Reorders points given in input order into kd order, the order of the
// leaves of a kd tree split at medians down to single points: each half of
// a half is a compact cell, so that a neighbourhood lies in one stretch of
// memory, and a Point_tree on any of the points follows those halves
// without a sort of its own.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Indexed_points sort_spatially(Array<Working_point> points_in_input_order)
{
  // sorted with their input positions rather than through them, so that the
  // sort reads memory in order
  Array<Positioned_point> sorted;
  sorted.reserve(points_in_input_order.size());
  for (std::size_t i = 0; i < points_in_input_order.size(); ++i)
    sorted.emplace_back(points_in_input_order[i], Index(i));
  Array<Working_point>().swap(points_in_input_order);
  sort_in_kd_order<ConcurrencyTag>(sorted.data(), sorted.data() + sorted.size());

  Indexed_points result;
  result.points.reserve(sorted.size());
  result.input_position.reserve(sorted.size());
  for (const Positioned_point& p : sorted)
  {
    result.points.push_back(p.first);
    result.input_position.push_back(p.second);
  }
  return result;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_POINTS_H
