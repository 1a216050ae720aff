// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The relocation that ends the default mode: Lloyd's relaxation restricted
// to the input points.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The Voronoi cells of the present points (the sites) among the input
// points: each input point falls in the cell of its nearest site (ties by
// input position).
struct Voronoi_cells
{
  Array<Index> sites;    // the present points, by index
  Array<Index> site_of;  // for each point, the rank of its site in `sites`
};

template <typename ConcurrencyTag>
Voronoi_cells voronoi_cells(const Indexed_points& points, const Array<char>& present)
{
  Voronoi_cells cells;
  Array<Index>& rank = cells.site_of; // the rank of each site, filled in first
  rank.assign(points.size(), 0);
  for (Index i = 0; i < Index(points.size()); ++i)
    if (present[i])
    {
      rank[i] = Index(cells.sites.size());
      cells.sites.push_back(i);
    }
  const Point_tree tree(points, cells.sites.begin(), cells.sites.end(), ConcurrencyTag());
  // a site is its own nearest, which the search leaves out; the others read
  // the rank of a site, which is never overwritten
  for_each_index<ConcurrencyTag>(
    points.size(),
    [&](std::size_t i) {
      if (!present[i])
        rank[i] = rank[tree.nearest_one(Index(i))];
    },
    [](std::size_t) { return true; });
  return cells;
}

// The members of each cell, in input order: those of cell c at
// members[first[c], first[c + 1]).
struct Cell_members
{
  Array<std::size_t> first;
  Array<Index> members;
};

// Counted into place by cell, then sorted by input position within each
// cell: the cells are small, and their members close in the internal order.
template <typename ConcurrencyTag>
Cell_members members_by_cell(const Indexed_points& points, const Voronoi_cells& cells)
{
  Cell_members result;
  result.first.assign(cells.sites.size() + 1, 0);
  for (Index c : cells.site_of)
    ++result.first[c + 1];
  for (std::size_t c = 0; c < cells.sites.size(); ++c)
    result.first[c + 1] += result.first[c];
  Array<std::size_t> next(result.first.begin(), result.first.end() - 1);
  result.members.resize(points.size());
  for (Index i = 0; i < Index(points.size()); ++i)
    result.members[next[cells.site_of[i]]++] = i;
  for_each_index<ConcurrencyTag>(
    cells.sites.size(),
    [&](std::size_t c) {
      std::sort(result.members.begin() + std::ptrdiff_t(result.first[c]),
                result.members.begin() + std::ptrdiff_t(result.first[c + 1]),
                [&](Index a, Index b) { return points.input_position[a] < points.input_position[b]; });
    },
    [](std::size_t) { return true; });
  return result;
}

// The member of a cell nearest its centroid (ties by input position). The
// centroid sums its members in input order, so that it does not depend on
// the internal order.
inline Index member_nearest_centroid(const Indexed_points& points, const Index* first, const Index* beyond)
{
  const Working_point centroid = centroid_of(std::size_t(beyond - first), [&](std::size_t j) -> const Working_point& {
    return points.points[first[j]];
  });
  Neighbor best{ std::numeric_limits<double>::infinity(), 0, 0 };
  for (const Index* i = first; i != beyond; ++i)
  {
    const Neighbor candidate{ squared_distance(points.points[*i], centroid), points.input_position[*i], *i };
    if (candidate < best)
      best = candidate;
  }
  return best.id;
}

// The member of each cell nearest its centroid, as the new present points.
template <typename ConcurrencyTag>
Array<char> members_nearest_centroids(const Indexed_points& points, const Voronoi_cells& cells)
{
  const Cell_members cell = members_by_cell<ConcurrencyTag>(points, cells);
  Array<Index> chosen(cells.sites.size());
  for_each_index<ConcurrencyTag>(
    cells.sites.size(),
    [&](std::size_t c) {
      chosen[c] = member_nearest_centroid(points, cell.members.data() + cell.first[c],
                                          cell.members.data() + cell.first[c + 1]);
    },
    [](std::size_t) { return true; });
  Array<char> present(points.size(), 0);
  for (Index i : chosen)
    present[i] = 1;
  return present;
}

// Lloyd's relaxation restricted to the input points, `iterations` times:
// each input point joins the cell of its nearest present point, and each
// cell keeps its member nearest its centroid. The count does not change.
// Returns the pairs (point no longer present, point present instead), both
// taken in input order.
template <typename ConcurrencyTag>
Array<std::pair<Index, Index> > relocate_within_input(const Indexed_points& points,
                                                            Array<char>& present, int iterations)
{
  const Array<char> before = present;
  const Array<Index> by_input = indices_by_input_position(points);
  for (int iteration = 0; iteration < iterations; ++iteration)
    present = members_nearest_centroids<ConcurrencyTag>(points, voronoi_cells<ConcurrencyTag>(points, present));

  Array<Index> gone, come;
  for (Index i : by_input)
  {
    if (before[i] && !present[i])
      gone.push_back(i);
    if (!before[i] && present[i])
      come.push_back(i);
  }
  Array<std::pair<Index, Index> > swaps;
  for (std::size_t j = 0; j < gone.size(); ++j)
    swaps.emplace_back(gone[j], come[j]);
  return swaps;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H
