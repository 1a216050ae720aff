// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the default mode's relocations share: input points grouped by cell,
// and the merits of a cell's candidate as its median, the representative
// whose distances to the cell's points sum least.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_CELL_MEDIANS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_CELL_MEDIANS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The cell of a point that belongs to none.
constexpr Index no_cell = (std::numeric_limits<Index>::max)();

// The members of each cell: those of cell c at [begin(c), end(c)).
struct Cell_members
{
  Array<std::size_t> first;
  Array<Index> members;

  const Index* begin(std::size_t c) const { return members.data() + first[c]; }
  const Index* end(std::size_t c) const { return members.data() + first[c + 1]; }
};

// The `items` grouped by cell, in the order of `items` within each cell, by
// counting: `cell_of(i)` is the cell of item `i`, below `cells`, or
// `no_cell` to leave it out.
template <typename Items, typename CellOf>
Cell_members group_by_cell(std::size_t cells, const Items& items, const CellOf& cell_of)
{
  Cell_members result;
  result.first.assign(cells + 1, 0);
  for (Index i : items)
    if (const Index c = cell_of(i); c != no_cell)
      ++result.first[c + 1];
  for (std::size_t c = 0; c < cells; ++c)
    result.first[c + 1] += result.first[c];
  result.members.resize(result.first.back());
  Array<std::size_t> next(result.first.begin(), result.first.end() - 1);
  for (Index i : items)
    if (const Index c = cell_of(i); c != no_cell)
      result.members[next[c]++] = i;
  return result;
}

// A candidate's merits as the representative of its cell: the sum of its
// distances to the members, summed in the members' order (input order, so
// that it does not depend on the internal order), and the square of the
// greatest.
struct Merits
{
  Neighbor member;
  double distance_sum;
  double squared_radius;
};

// Adds to `merits` the distances from `at` to the `count` members whose
// j-th is at `member_point(j)`, in that order.
template <typename MemberPoint>
void add_distances(Merits& merits, std::size_t count, const MemberPoint& member_point, const Working_point& at)
{
  for (std::size_t j = 0; j < count; ++j)
  {
    const double d2 = squared_distance(member_point(j), at);
    merits.distance_sum += std::sqrt(d2);
    merits.squared_radius = (std::max)(merits.squared_radius, d2);
  }
}

// The merits of `member` among the members [first, beyond).
inline Merits merits_of(const Indexed_points& points, const Index* first, const Index* beyond, Neighbor member)
{
  Merits r{ member, 0., 0. };
  add_distances(
    r, std::size_t(beyond - first), [&](std::size_t j) -> const Working_point& { return points.points[first[j]]; },
    points.points[member.id]);
  return r;
}

// Whether `a` is nearer than `b` to being the cell's median: a lesser
// distance sum, ties broken by the lower input position.
inline bool nearer_median(const Merits& a, const Merits& b)
{
  return a.distance_sum < b.distance_sum ||
         (a.distance_sum == b.distance_sum && a.member.input_position < b.member.input_position);
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_CELL_MEDIANS_H
