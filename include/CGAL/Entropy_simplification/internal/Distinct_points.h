// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Coincident points collapsed to one representative before either mode runs.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <functional>
#include <tuple>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The points of a range with every group of coincident points (equal as
// doubles, so -0.0 equals 0.0) reduced to its first in input order.
//
// Both modes would otherwise suffer copies: c copies of a point are each
// other's neighbours at distance 0, so the default mode's neighbour lists and
// the paper mode's exact updates grow as c^2, and the copies' normals and
// entropies are undefined. A copy adds nothing to the geometry, so copies are
// removed before any distinct point and return, in input order, only once
// every distinct point is kept.
struct Distinct_points
{
  Array<Working_point> points;  // the representatives, in input order
  Array<Index> input_position;  // of each representative
  Array<Index> copies;          // input positions of the other points, ascending
  Array<Index> representative;  // for each copy, the index of its representative in `points`

  std::size_t size() const { return input_position.size(); }
};

// Sorting is O(n log n) whatever the number of copies, and sorting by
// coordinates then position makes the first of each run of equal points the
// earliest in input order.
// The order is total (positions differ), so a parallel sort gives the same.
template <typename ConcurrencyTag>
Distinct_points collapse_duplicates(Array<Working_point> points)
{
  // the copies are sorted themselves, not their indices: a sort that moves
  // them reads memory in order, where one through indices would not
  struct Positioned_point
  {
    std::tuple<double, double, double, Index> key;
    bool operator<(const Positioned_point& other) const { return key < other.key; }
  };
  Array<Positioned_point> sorted(points.size());
  for_each_index<ConcurrencyTag>(
    points.size(),
    [&](std::size_t i) { sorted[i].key = std::make_tuple(points[i].x(), points[i].y(), points[i].z(), Index(i)); },
    [](std::size_t) { return true; });
  sort_by<ConcurrencyTag>(sorted.begin(), sorted.end(), std::less<Positioned_point>());

  // the input position of the representative of each point
  Array<Index> first(points.size());
  Index representative = 0;
  for (std::size_t r = 0; r < sorted.size(); ++r)
  {
    const auto& [x, y, z, position] = sorted[r].key;
    const auto& [px, py, pz, previous] = sorted[r == 0 ? 0 : r - 1].key;
    if (r == 0 || !(x == px && y == py && z == pz))
      representative = position;
    first[position] = representative;
  }
  Array<Positioned_point>().swap(sorted);

  // The representatives move to the front of `points`, in input order: each
  // goes to a slot at or before its own, so the compaction is in place. The
  // slot of each representative is where it goes.
  Distinct_points result;
  Array<Index> slot(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (first[i] == i)
    {
      slot[i] = Index(result.input_position.size());
      points[slot[i]] = points[i];
      result.input_position.push_back(Index(i));
    }
    else
    {
      result.copies.push_back(Index(i));
      result.representative.push_back(slot[first[i]]);
    }
  }
  points.resize(result.input_position.size());
  result.points = std::move(points);
  return result;
}

// The input positions of the `distinct_count` representatives, ascending:
// those of no copy, `copies` being ascending.
inline Array<Index> positions_of_no_copy(const Array<Index>& copies, std::size_t distinct_count)
{
  Array<Index> positions;
  positions.reserve(distinct_count);
  std::size_t c = 0;
  for (Index p = 0; positions.size() < distinct_count; ++p)
  {
    if (c < copies.size() && copies[c] == p)
      ++c;
    else
      positions.push_back(p);
  }
  return positions;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DISTINCT_POINTS_H
