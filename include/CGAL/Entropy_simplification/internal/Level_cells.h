// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cells that relocate the levels of detail of a default-mode ranking:
// the prefixes a ranking passes through are moved toward the centroids of
// the input points they stand for, as a direct call's relocation moves its
// result, without breaking their nesting.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LEVEL_CELLS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LEVEL_CELLS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>

#include <array>
#include <cstdint>
#include <limits>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The count at which a stage of a ranking's elimination among its kept
// points ends: the largest of 50, 20, 10, 5, 2, 1, 0.5, ...% of the n
// points (rounded up) below `present`, or 0 when none is. Users cut levels of detail at such round
// fractions, and each of them is relocated.
inline std::size_t level_boundary_below(std::size_t present, std::size_t n)
{
  std::uint64_t power = 10;
  for (; power <= std::uint64_t(10) * n; power *= 10)
    for (std::uint64_t mantissa : { 5, 2, 1 })
    {
      const std::uint64_t boundary = (std::uint64_t(n) * mantissa + power - 1) / power;
      if (boundary < present)
        return std::size_t(boundary);
    }
  return 0;
}

// Each input point belongs to one cell, which has at most one present
// point: at first, that of the present point nearest it. A point removed at
// a level boundary's stage brings its cell into that of its nearest present
// neighbour; each cell is then represented by the point, present or removed
// in that stage, nearest its centroid. The points removed before the stage
// stay removed, so that the levels above keep their points, and each level's
// points stand for the input points nearest them, as a direct call's
// relocated ones do.
class Level_cells
{
public:
  // `site[i]` is the present point whose cell holds `i`: `i` itself when
  // present. The sums of the cells start in input order, and a join adds
  // one cell's sums to the other's: they follow the order of the joins,
  // not the internal order, and no pass over every point is needed later.
  Level_cells(const Indexed_points& points, const Array<Index>& by_input, Array<Index> site)
    : m_parent(std::move(site)), m_sum(points.size(), Sum{ 0., 0., 0., 0. }), m_slot(points.size(), no_slot)
  {
    for (Index i : by_input)
      add(m_sum[m_parent[i]], Sum{ points.points[i].x(), points.points[i].y(), points.points[i].z(), 1. });
  }

  // Merges the cell of `removed` into that of `site`.
  void join(Index removed, Index site)
  {
    const Index from = cell_of(removed), to = cell_of(site);
    add(m_sum[to], m_sum[from]);
    m_parent[from] = to;
  }

  // Replaces each of the present `sites` by the member of its cell nearest
  // the cell's centroid, among it and the `stage_removed` points (in
  // removal order): a site that leaves takes the place, in `stage_removed`,
  // of the point that replaces it. Returns the points that became present.
  Array<Index> move_toward_centroids(const Indexed_points& points, const Array<Index>& sites,
                                           Array<char>& present, Array<Index>& stage_removed)
  {
    Array<Working_point> centroid;
    Array<Neighbor> best;
    centroid.reserve(sites.size());
    best.reserve(sites.size());
    for (Index s : sites)
    {
      const Index cell = cell_of(s);
      const Sum& sum = m_sum[cell];
      m_slot[cell] = Index(centroid.size());
      centroid.emplace_back(sum[0] / sum[3], sum[1] / sum[3], sum[2] / sum[3]);
      best.push_back(Neighbor{ squared_distance(points.points[s], centroid.back()), points.input_position[s], s });
    }
    for (Index r : stage_removed)
      if (const Index slot = m_slot[cell_of(r)]; slot != no_slot)
      {
        const Neighbor candidate{ squared_distance(points.points[r], centroid[slot]), points.input_position[r], r };
        if (candidate < best[slot])
          best[slot] = candidate;
      }
    Array<Index> arrived;
    for (Index& r : stage_removed)
      if (const Index slot = m_slot[cell_of(r)]; slot != no_slot && best[slot].id == r)
      {
        present[sites[slot]] = 0;
        present[r] = 1;
        arrived.push_back(r);
        r = sites[slot];
      }
    for (Index s : sites)
      m_slot[cell_of(s)] = no_slot;
    return arrived;
  }

private:
  using Sum = std::array<double, 4>; // x, y, z and the number of points
  static constexpr Index no_slot = (std::numeric_limits<Index>::max)();

  static void add(Sum& to, const Sum& from)
  {
    for (int c = 0; c < 4; ++c)
      to[c] += from[c];
  }

  // The root of the cell of `i`, halving the paths on the way.
  Index cell_of(Index i)
  {
    while (m_parent[i] != i)
      i = m_parent[i] = m_parent[m_parent[i]];
    return i;
  }

  Array<Index> m_parent;
  Array<Sum> m_sum;    // by cell root
  Array<Index> m_slot; // by cell root, the rank of its present point among the sites, while relocating
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LEVEL_CELLS_H
