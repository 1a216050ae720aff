// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The relocation that ends the default mode: Lloyd's relaxation restricted
// to the input points.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H

#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The indices of the points in input order.
inline std::vector<Index> indices_by_input_position(const Indexed_points& points)
{
  std::vector<Index> by_input(points.size());
  for (Index i = 0; i < Index(points.size()); ++i)
    by_input[points.input_position[i]] = i;
  return by_input;
}

// The Voronoi cells of the present points (the sites) among the input
// points: each input point falls in the cell of its nearest site (ties by
// input position).
struct Voronoi_cells
{
  std::vector<Index> sites;    // the present points, by index
  std::vector<Index> site_of;  // for each point, the rank of its site in `sites`
};

template <typename ConcurrencyTag>
Voronoi_cells voronoi_cells(const Indexed_points& points, const std::vector<char>& present)
{
  Voronoi_cells cells;
  std::vector<Index>& rank = cells.site_of; // the rank of each site, filled in first
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
      thread_local std::vector<Neighbor> nearest;
      if (!present[i])
      {
        tree.nearest(Index(i), 1, nearest);
        rank[i] = rank[nearest.front().id];
      }
    },
    [](std::size_t) { return true; });
  return cells;
}

// The member of each cell nearest the cell's centroid (ties by input
// position), as the new present points. Sums run in input order, so that
// they do not depend on the internal order.
inline std::vector<char> members_nearest_centroids(const Indexed_points& points, const Voronoi_cells& cells,
                                                   const std::vector<Index>& by_input)
{
  const std::size_t m = cells.sites.size();
  std::vector<std::array<double, 4> > sum(m, { 0., 0., 0., 0. });
  for (Index i : by_input)
  {
    const Working_point& p = points.points[i];
    std::array<double, 4>& s = sum[cells.site_of[i]];
    s[0] += p.x();
    s[1] += p.y();
    s[2] += p.z();
    s[3] += 1.;
  }
  std::vector<Neighbor> best(m, Neighbor{ std::numeric_limits<double>::infinity(), 0, 0 });
  for (Index i : by_input)
  {
    const Index c = cells.site_of[i];
    const Working_point centroid(sum[c][0] / sum[c][3], sum[c][1] / sum[c][3], sum[c][2] / sum[c][3]);
    const Neighbor candidate{ squared_distance(points.points[i], centroid), points.input_position[i], i };
    if (candidate < best[c])
      best[c] = candidate;
  }
  std::vector<char> present(points.size(), 0);
  for (const Neighbor& b : best)
    present[b.id] = 1;
  return present;
}

// Lloyd's relaxation restricted to the input points, `iterations` times:
// each input point joins the cell of its nearest present point, and each
// cell keeps its member nearest its centroid. The count does not change.
// Returns the pairs (point no longer present, point present instead), both
// taken in input order.
template <typename ConcurrencyTag>
std::vector<std::pair<Index, Index> > relocate_within_input(const Indexed_points& points,
                                                            std::vector<char>& present, int iterations)
{
  const std::vector<char> before = present;
  const std::vector<Index> by_input = indices_by_input_position(points);
  for (int iteration = 0; iteration < iterations; ++iteration)
    present = members_nearest_centroids(points, voronoi_cells<ConcurrencyTag>(points, present), by_input);

  std::vector<Index> gone, come;
  for (Index i : by_input)
  {
    if (before[i] && !present[i])
      gone.push_back(i);
    if (!before[i] && present[i])
      come.push_back(i);
  }
  std::vector<std::pair<Index, Index> > swaps;
  for (std::size_t j = 0; j < gone.size(); ++j)
    swaps.emplace_back(gone[j], come[j]);
  return swaps;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H
