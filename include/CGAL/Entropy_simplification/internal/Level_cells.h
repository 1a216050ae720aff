// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cells that relocate the levels of detail of a default-mode ranking:
// the prefixes a ranking passes through are moved to the medians of the
// input points they stand for, as a direct call's relocation moves its
// result, without breaking their nesting.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LEVEL_CELLS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LEVEL_CELLS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Cell_medians.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
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
// neighbour; each cell is then represented by its median among the point
// present and those removed in that stage, as a direct call's relocation
// takes its cells' medians. While every input point follows the present
// points, the cells then become those of the points' nearest present
// points (take_cells_of_nearest), and their medians move in once more. The
// points removed before the stage stay removed, so that the levels above
// keep their points, and each level's points stand for the input points
// nearest them, as a direct call's relocated ones do.
class Level_cells
{
public:
  // `site[i]` is the present point whose cell holds `i`: `i` itself when
  // present. `by_input` lists the points in input order, the order in which
  // each candidate's distances are summed.
  Level_cells(Array<Index> by_input, Array<Index> site)
    : m_by_input(std::move(by_input)), m_parent(std::move(site))
  {
  }

  // The points in input order.
  const Array<Index>& by_input() const { return m_by_input; }

  // Makes the cell of each point `i` that of `nearest[i]`, its nearest
  // present point (itself when present), as a step of Lloyd's would.
  void take_cells_of_nearest(const Array<Index>& nearest) { m_parent = nearest; }

  // Merges the cell of `removed` into that of `site`.
  void join(Index removed, Index site) { m_parent[cell_of(removed)] = cell_of(site); }

  // Replaces each of the present `sites` by the median of its cell among it
  // and the `stage_removed` points of the cell: the candidate whose
  // distances to the cell's points, summed in input order, sum least (ties:
  // the lowest input position). A site that leaves takes the place, in
  // `stage_removed`, of the point that replaces it. Returns the points that
  // became present.
  template <typename ConcurrencyTag>
  Array<Index> move_to_medians(const Indexed_points& points, const Array<Index>& sites, Array<char>& present,
                               Array<Index>& stage_removed)
  {
    const Array<Index> cell = site_rank_of_each_point<ConcurrencyTag>(sites);
    const auto cell_of_point = [&](Index i) { return cell[i]; };
    Array<Index> candidates(sites.begin(), sites.end());
    candidates.insert(candidates.end(), stage_removed.begin(), stage_removed.end());
    const Array<Index> median = medians<ConcurrencyTag>(points, group_by_cell(sites.size(), candidates, cell_of_point),
                                                        group_by_cell(sites.size(), m_by_input, cell_of_point));
    Array<Index> arrived;
    for (Index& r : stage_removed)
      if (const Index c = cell[r]; c != no_cell && median[c] == r)
      {
        present[sites[c]] = 0;
        present[r] = 1;
        arrived.push_back(r);
        r = sites[c];
      }
    return arrived;
  }

private:
  // For each point, the rank among the `sites` of its cell's site, or
  // `no_cell` if its cell has none. The paths are replaced by their roots,
  // found in parallel by walking them without writing.
  template <typename ConcurrencyTag>
  Array<Index> site_rank_of_each_point(const Array<Index>& sites)
  {
    Array<Index> root(m_parent.size());
    for_each_index<ConcurrencyTag>(
      root.size(),
      [&](std::size_t i) {
        Index r = Index(i);
        while (m_parent[r] != r)
          r = m_parent[r];
        root[i] = r;
      },
      [](std::size_t) { return true; });
    m_parent.swap(root);
    Array<Index>& rank_of_root = root; // the old parents are no longer needed
    std::fill(rank_of_root.begin(), rank_of_root.end(), no_cell);
    for (std::size_t c = 0; c < sites.size(); ++c)
      rank_of_root[m_parent[sites[c]]] = Index(c);
    Array<Index> rank(m_parent.size());
    for_each_index<ConcurrencyTag>(
      rank.size(), [&](std::size_t i) { rank[i] = rank_of_root[m_parent[i]]; }, [](std::size_t) { return true; });
    return rank;
  }

  // Each cell's median: its candidate of least distance sum to its members
  // (ties by input position), the first candidate, the site, being one. The
  // cells run in parallel, and when they are few, as at the coarsest
  // levels where a few cells hold every point, so do their candidates.
  // Each cell keeps its candidates' merits where it runs (see
  // median_of_cell): at the 50% boundary of 1,000,000 points, an array of
  // every candidate's merits took longer to allocate (110 ms, page faults)
  // than their sums.
  template <typename ConcurrencyTag>
  static Array<Index> medians(const Indexed_points& points, const Cell_members& candidates,
                              const Cell_members& members)
  {
    // below this many cells, the cells alone would leave most threads idle
    // on a machine of many (the last boundaries have 2, 5, 10, 20 and 50)
    constexpr std::size_t few_cells = 64;
    Array<Index> median(candidates.first.size() - 1);
    const bool candidates_in_parallel =
      std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && median.size() < few_cells;
    for_each_index<ConcurrencyTag>(
      median.size(),
      [&](std::size_t c) {
        median[c] = median_of_cell<ConcurrencyTag>(points, candidates, members, c, candidates_in_parallel);
      },
      [](std::size_t) { return true; });
    return median;
  }

  // The median of cell `c` (see medians), its candidates' sums computed in
  // parallel when `in_parallel`, a candidate each.
  template <typename ConcurrencyTag>
  static Index median_of_cell(const Indexed_points& points, const Cell_members& candidates,
                              const Cell_members& members, std::size_t c, bool in_parallel)
  {
    const Index* candidate = candidates.begin(c);
    const std::size_t count = std::size_t(candidates.end(c) - candidate);
    if (count == 1) // the site alone: no point that the stage removed joined its cell
      return candidate[0];
    // a few candidates' merits on the stack: a ranking with no level has
    // half as many cells as points at its first boundary
    constexpr std::size_t on_stack = 8;
    Merits merits_on_stack[on_stack];
    Array<Merits> merits_on_heap(count > on_stack ? count : 0);
    Merits* merits = count > on_stack ? merits_on_heap.data() : merits_on_stack;
    for (std::size_t k = 0; k < count; ++k)
      merits[k] = Merits{ Neighbor{ 0., points.input_position[candidate[k]], candidate[k] }, 0., 0. };
    if (!in_parallel)
      add_member_distances(points, members.begin(c), members.end(c), merits, count);
    else
      for_each_index<ConcurrencyTag>(
        count, [&](std::size_t k) { add_member_distances(points, members.begin(c), members.end(c), merits + k, 1); },
        [](std::size_t) { return true; });
    return nearest_median(count, [&](std::size_t k) { return merits[k]; });
  }

  // Adds to the merits of each of the `count` candidates `merits[k]` the
  // members' distances, in the members' order (see add_distances). The members, scattered in memory, are read a block at a time into
  // a small copy over which each candidate sums in turn. At the coarsest
  // levels of a ranking, where a few cells hold every point, reading them
  // from the points for each candidate took the medians of a ranking of
  // 300,000 points from 0.07 s to 0.36 s (with a level at 1%); a copy of
  // each cell whole, new memory, took 26 ms at each of the last two
  // boundaries of 1,000,000 points, mostly in page faults, and blocks 9 ms.
  static void add_member_distances(const Indexed_points& points, const Index* first, const Index* beyond,
                                   Merits* merits, std::size_t count)
  {
    constexpr std::size_t block = 256;
    Working_point copy[block];
    while (first < beyond)
    {
      const std::size_t size = (std::min)(block, std::size_t(beyond - first));
      for (std::size_t j = 0; j < size; ++j)
        copy[j] = points.points[first[j]];
      for (std::size_t k = 0; k < count; ++k)
        add_distances(
          merits[k], size, [&](std::size_t j) -> const Working_point& { return copy[j]; },
          points.points[merits[k].member.id]);
      first += size;
    }
  }

  // The median among `count` candidates, `merits(k)` giving the k-th's
  // merits (see nearer_median).
  template <typename MeritsOf>
  static Index nearest_median(std::size_t count, const MeritsOf& merits)
  {
    CGAL_assertion(count > 0);
    Merits best = merits(0);
    for (std::size_t k = 1; k < count; ++k)
      if (const Merits m = merits(k); nearer_median(m, best))
        best = m;
    return best.member.id;
  }

  // The root of the cell of `i`, halving the paths on the way.
  Index cell_of(Index i)
  {
    while (m_parent[i] != i)
      i = m_parent[i] = m_parent[m_parent[i]];
    return i;
  }

  Array<Index> m_by_input;
  Array<Index> m_parent;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LEVEL_CELLS_H
