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

// For each input point, the present point nearest to it (ties by input
// position): the Voronoi cell of the present points it falls in.
template <typename ConcurrencyTag>
std::vector<Index> voronoi_cells(const Indexed_points& points, const std::vector<char>& present)
{
  std::vector<Index> sites;
  for (Index i = 0; i < Index(points.size()); ++i)
    if (present[i])
      sites.push_back(i);
  const Point_tree tree(points, sites.begin(), sites.end());
  std::vector<Index> cell(points.size());
  for_each_index<ConcurrencyTag>(
    points.size(),
    [&](std::size_t i) {
      thread_local std::vector<Neighbor> nearest;
      // a site is its own nearest, which the search leaves out
      if (present[i])
        cell[i] = Index(i);
      else
      {
        tree.nearest(Index(i), 1, nearest);
        cell[i] = nearest.front().id;
      }
    },
    [](std::size_t) { return true; });
  return cell;
}

// The member of each cell nearest the cell's centroid (ties by input
// position), as the new present points. Sums run in input order, so that
// they do not depend on the internal order.
inline std::vector<char> members_nearest_centroids(const Indexed_points& points, const std::vector<Index>& cell,
                                                   const std::vector<Index>& by_input)
{
  const std::size_t n = points.size();
  std::vector<std::array<double, 4> > sum(n, { 0., 0., 0., 0. });
  for (Index i : by_input)
  {
    const Working_point& p = points.points[i];
    std::array<double, 4>& s = sum[cell[i]];
    s[0] += p.x();
    s[1] += p.y();
    s[2] += p.z();
    s[3] += 1.;
  }
  std::vector<Neighbor> best(n, Neighbor{ std::numeric_limits<double>::infinity(), 0, 0 });
  for (Index i : by_input)
  {
    const std::array<double, 4>& s = sum[cell[i]];
    const Working_point centroid(s[0] / s[3], s[1] / s[3], s[2] / s[3]);
    const Neighbor candidate{ squared_distance(points.points[i], centroid), points.input_position[i], i };
    if (candidate < best[cell[i]])
      best[cell[i]] = candidate;
  }
  std::vector<char> present(n, 0);
  for (std::size_t c = 0; c < n; ++c)
    if (cell[c] == c)
      present[best[c].id] = 1;
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
