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
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <cmath>
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
// neighbour; each cell is then represented by its median among the point
// present and those removed in that stage, as a direct call's relocation
// takes its cells' medians. The points removed before the stage stay
// removed, so that the levels above keep their points, and each level's
// points stand for the input points nearest them, as a direct call's
// relocated ones do.
class Level_cells
{
public:
  // `site[i]` is the present point whose cell holds `i`: `i` itself when
  // present. `by_input` lists the points in input order, the order in which
  // each candidate's distances are summed.
  Level_cells(Array<Index> by_input, Array<Index> site)
    : m_by_input(std::move(by_input)), m_parent(std::move(site)), m_slot(m_parent.size(), no_slot)
  {
  }

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
    for (std::size_t c = 0; c < sites.size(); ++c)
      m_slot[cell_of(sites[c])] = Index(c);
    const Cell_lists candidates = candidates_by_cell(sites, stage_removed);
    const Cell_lists members = members_by_cell(sites.size());
    Array<Index> median(sites.size());
    for_each_index<ConcurrencyTag>(
      sites.size(),
      [&](std::size_t c) {
        median[c] = median_of(points, candidates.of(c), members.of(c));
      },
      [](std::size_t) { return true; });
    for (Index s : sites)
      m_slot[cell_of(s)] = no_slot;

    Array<Index> arrived;
    Array<Index> site_of_candidate(present.size(), no_slot);
    for (std::size_t c = 0; c < sites.size(); ++c)
      if (median[c] != sites[c])
        site_of_candidate[median[c]] = Index(c);
    for (Index& r : stage_removed)
      if (const Index c = site_of_candidate[r]; c != no_slot)
      {
        present[sites[c]] = 0;
        present[r] = 1;
        arrived.push_back(r);
        r = sites[c];
      }
    return arrived;
  }

private:
  static constexpr Index no_slot = (std::numeric_limits<Index>::max)();

  // Lists by cell: those of cell c at items[first[c], first[c + 1]).
  struct Cell_lists
  {
    Array<std::size_t> first;
    Array<Index> items;
    std::pair<const Index*, const Index*> of(std::size_t c) const
    {
      return { items.data() + first[c], items.data() + first[c + 1] };
    }
  };

  // Counted into place: the slot of each item's cell, `slot(i)`, is known.
  template <typename Items, typename SlotOf>
  static Cell_lists lists_by_slot(std::size_t cells, const Items& items, const SlotOf& slot)
  {
    Cell_lists lists;
    lists.first.assign(cells + 1, 0);
    for (Index i : items)
      if (const Index c = slot(i); c != no_slot)
        ++lists.first[c + 1];
    for (std::size_t c = 0; c < cells; ++c)
      lists.first[c + 1] += lists.first[c];
    lists.items.resize(lists.first.back());
    Array<std::size_t> next(lists.first.begin(), lists.first.end() - 1);
    for (Index i : items)
      if (const Index c = slot(i); c != no_slot)
        lists.items[next[c]++] = i;
    return lists;
  }

  // Each cell's site, then its points removed in the stage.
  Cell_lists candidates_by_cell(const Array<Index>& sites, const Array<Index>& stage_removed)
  {
    Array<Index> all(sites.begin(), sites.end());
    all.insert(all.end(), stage_removed.begin(), stage_removed.end());
    return lists_by_slot(sites.size(), all, [&](Index i) { return m_slot[cell_of(i)]; });
  }

  // Each cell's points in input order; those of cells without a present
  // point are left out.
  Cell_lists members_by_cell(std::size_t cells)
  {
    return lists_by_slot(cells, m_by_input, [&](Index i) { return m_slot[cell_of(i)]; });
  }

  static Index median_of(const Indexed_points& points, std::pair<const Index*, const Index*> candidates,
                         std::pair<const Index*, const Index*> members)
  {
    Index best = *candidates.first;
    double best_sum = std::numeric_limits<double>::infinity();
    for (const Index* c = candidates.first; c != candidates.second; ++c)
    {
      double sum = 0.;
      for (const Index* m = members.first; m != members.second; ++m)
        sum += std::sqrt(squared_distance(points.points[*m], points.points[*c]));
      if (sum < best_sum || (sum == best_sum && points.input_position[*c] < points.input_position[best]))
      {
        best = *c;
        best_sum = sum;
      }
    }
    return best;
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
  Array<Index> m_slot; // by cell root, the rank of its present point among the sites, while relocating
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LEVEL_CELLS_H
