// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The relocation that ends the default mode: a relaxation in Lloyd's manner
// restricted to the input points, each cell keeping its median.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Cell_medians.h>
#include <CGAL/Entropy_simplification/internal/Coverage_swaps.h>
#include <CGAL/Entropy_simplification/internal/Default_mode_terms.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Nearest_present_points.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/assertions.h>

#include <boost/range/irange.hpp>

#include <algorithm>
#include <array>
#include <cmath>
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

// The cells from `nearest`, each point's nearest present point (see
// nearest_present_points), whose memory they take.
template <typename ConcurrencyTag>
Voronoi_cells voronoi_cells(const Array<char>& present, Array<Index> nearest)
{
  CGAL_precondition(nearest.size() == present.size());
  Voronoi_cells cells;
  Array<Index>& rank = cells.site_of = std::move(nearest);
  for (Index i = 0; i < Index(rank.size()); ++i)
    if (present[i])
    {
      rank[i] = Index(cells.sites.size());
      cells.sites.push_back(i);
    }
  // the others read the rank that took the place of their site, which is
  // never overwritten
  for_each_index<ConcurrencyTag>(
    rank.size(),
    [&](std::size_t i) {
      if (!present[i])
      {
        CGAL_assertion(present[rank[i]]);
        rank[i] = rank[rank[i]];
      }
    },
    [](std::size_t) { return true; });
  return cells;
}

// The members of each cell in input order, grouped in the internal order,
// then sorted by input position within each cell: the cells are small, and
// their members close in the internal order.
template <typename ConcurrencyTag>
Cell_members members_by_cell(const Indexed_points& points, const Voronoi_cells& cells)
{
  Cell_members result = group_by_cell(cells.sites.size(), boost::irange(Index(0), Index(points.size())),
                                      [&](Index i) { return cells.site_of[i]; });
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

// The members that may represent a cell: the few nearest its centroid.
// Among them, the one with the least sum of distances to the members suits
// the mean distance to the kept points best (it is the median of the cell,
// where the centroid is the mean). Taking 8 or 16 moved the mean distance by
// under 0.05% on the benchmark's inputs.
constexpr std::size_t candidates_per_cell = 4;

// The members of a cell nearest its centroid, nearest first (ties by input
// position): at most `wanted`, kept sorted by insertion. The centroid sums
// the members in input order, so that it does not depend on the internal
// order.
template <std::size_t wanted>
std::array<Neighbor, candidates_per_cell> members_nearest_centroid(const Indexed_points& points, const Index* first,
                                                                   const Index* beyond, std::size_t& count)
{
  static_assert(wanted >= 1 && wanted <= candidates_per_cell, "a cell has room for so many candidates");
  const Working_point centroid = centroid_of(std::size_t(beyond - first), [&](std::size_t j) -> const Working_point& {
    return points.points[first[j]];
  });
  std::array<Neighbor, candidates_per_cell> nearest{};
  count = 0;
  for (const Index* i = first; i != beyond; ++i)
  {
    const Neighbor candidate{ squared_distance(points.points[*i], centroid), points.input_position[*i], *i };
    if (count == wanted && !(candidate < nearest[count - 1]))
      continue;
    std::size_t j = (std::min)(count, wanted - 1);
    for (; j > 0 && candidate < nearest[j - 1]; --j)
      nearest[j] = nearest[j - 1];
    nearest[j] = candidate;
    count = (std::min)(count + 1, wanted);
  }
  return nearest;
}

// The candidate of least distance sum (ties by input position) among the
// `candidates` members nearest the centroid whose radius is within
// `squared_bound`; the one nearest the centroid always is, the bound being
// at least its radius.
template <std::size_t candidates>
Index cell_median(const Indexed_points& points, const Index* first, const Index* beyond, double squared_bound)
{
  std::size_t count = 0;
  const std::array<Neighbor, candidates_per_cell> nearest =
    members_nearest_centroid<candidates>(points, first, beyond, count);
  Merits best = merits_of(points, first, beyond, nearest[0]);
  for (std::size_t c = 1; c < count; ++c)
  {
    const Merits r = merits_of(points, first, beyond, nearest[c]);
    if (r.squared_radius <= squared_bound && nearer_median(r, best))
      best = r;
  }
  return best.member.id;
}

// The square of the greatest distance from a cell's member nearest its
// centroid to the cell's members, over all cells. No median moving a cell's
// radius beyond it, the input stays as near the kept points as the members
// nearest the centroids would keep it. The candidates are found again once
// it is known rather than kept for every cell meanwhile, which would take
// about 80 bytes per kept point; the passes cost no measurable time.
template <typename ConcurrencyTag>
double greatest_squared_radius_about_centroids(const Indexed_points& points, const Cell_members& cell)
{
  Array<double> squared_radius(cell.first.size() - 1);
  for_each_index<ConcurrencyTag>(
    squared_radius.size(),
    [&](std::size_t c) {
      const Index* first = cell.begin(c);
      const Index* beyond = cell.end(c);
      std::size_t count = 0;
      squared_radius[c] =
        merits_of(points, first, beyond, members_nearest_centroid<1>(points, first, beyond, count)[0]).squared_radius;
    },
    [](std::size_t) { return true; });
  return squared_radius.empty() ? 0. : *std::max_element(squared_radius.begin(), squared_radius.end());
}

// The median of each cell, by the rank of its site, as the new present
// points; with the `terms` medians or radius_bound switched off, the member
// nearest the centroid, or the median whatever its radius.
template <typename ConcurrencyTag>
Array<Index> cell_medians(const Indexed_points& points, const Voronoi_cells& cells, const Default_mode_terms& terms)
{
  const Cell_members cell = members_by_cell<ConcurrencyTag>(points, cells);
  // the member nearest the centroid needs no bound
  const double squared_bound = terms.medians && terms.radius_bound
                                 ? greatest_squared_radius_about_centroids<ConcurrencyTag>(points, cell)
                                 : std::numeric_limits<double>::infinity();
  Array<Index> chosen(cells.sites.size());
  for_each_index<ConcurrencyTag>(
    cells.sites.size(),
    [&](std::size_t c) {
      const Index* first = cell.begin(c);
      const Index* beyond = cell.end(c);
      // the median of one candidate is the member nearest the centroid
      chosen[c] = terms.medians ? cell_median<candidates_per_cell>(points, first, beyond, squared_bound)
                                : cell_median<1>(points, first, beyond, squared_bound);
    },
    [](std::size_t) { return true; });
  return chosen;
}

// What a relocation changed: the pairs (point no longer present, point
// present instead), both taken in input order; and each point's nearest
// present point once relocated, when the coverage swaps found them, or
// nothing.
struct Relocation
{
  Array<std::pair<Index, Index> > swaps;
  Array<Index> site;
};

// A relaxation in Lloyd's manner restricted to the input points, `iterations` times:
// each input point joins the cell of its nearest present point, and each
// cell keeps its median (see cell_medians, and `terms`), the first time
// from `nearest`, the nearest present points the elimination left, unless
// it is empty (see nearest_present_points); then, with
// `terms.coverage_swaps`, the coverage swaps (see coverage_swap_count), each
// point's crowding measured against its `scale`. The count does not change.
// After the first time, each point's search for its nearest present point
// starts bounded by the median of its cell, when `offsets` do not answer it.
template <typename ConcurrencyTag>
Relocation relocate_within_input(const Indexed_points& points, Array<char>& present, int iterations,
                                 const Default_mode_terms& terms, const Array<double>& scale, Array<Index> nearest,
                                 const Neighbor_offsets& offsets = Neighbor_offsets())
{
  const Array<char> before = present;
  const Array<Index> by_input = indices_by_input_position(points);
  Array<Index> median_of_cell; // of each point's cell, once relocated
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    if (iteration > 0 || nearest.empty())
      nearest = nearest_present_points<ConcurrencyTag>(points, present, median_of_cell, offsets);
    Array<Index>().swap(median_of_cell); // not to be held while the cells are
    Voronoi_cells cells = voronoi_cells<ConcurrencyTag>(present, std::move(nearest));
    const Array<Index> medians = cell_medians<ConcurrencyTag>(points, cells, terms);
    present.assign(points.size(), 0);
    for (Index m : medians)
      present[m] = 1;
    median_of_cell = std::move(cells.site_of);
    for_each_index<ConcurrencyTag>(
      points.size(), [&](std::size_t i) { median_of_cell[i] = medians[median_of_cell[i]]; },
      [](std::size_t) { return true; });
  }
  Array<Index>().swap(nearest); // unused without iterations, not to be held through the swaps
  Relocation relocation;
  if (terms.coverage_swaps)
  {
    const std::size_t kept = std::size_t(std::count(present.begin(), present.end(), char(1)));
    relocation.site =
      swap_farthest_for_crowded<ConcurrencyTag>(points, present, coverage_swap_count(kept, points.size()), scale,
                                                std::move(median_of_cell), offsets);
  }

  Array<Index> gone, come;
  for (Index i : by_input)
  {
    if (before[i] && !present[i])
      gone.push_back(i);
    if (!before[i] && present[i])
      come.push_back(i);
  }
  for (std::size_t j = 0; j < gone.size(); ++j)
    relocation.swaps.emplace_back(gone[j], come[j]);
  return relocation;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LLOYD_RELOCATION_H
