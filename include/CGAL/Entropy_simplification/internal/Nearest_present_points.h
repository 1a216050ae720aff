// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Each point's nearest present point, searched in a tree of the present
// points, each search bounded from the start when a present point near it
// is known.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NEAREST_PRESENT_POINTS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NEAREST_PRESENT_POINTS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// For each point, the present point nearest it (ties by input position):
// itself when present. At least one point must be present. The first
// neighbours of `offsets`, unless empty, answer the searches they hold a
// present point for (see Neighbor_offsets). `hint`, unless empty, gives
// each point a present point, such as the median that took the place of
// its nearest, from which its search starts bounded, so that it visits
// only the leaves near the point.
template <typename ConcurrencyTag>
Array<Index> nearest_present_points(const Indexed_points& points, const Array<char>& present,
                                    const Array<Index>& hint = Array<Index>(),
                                    const Neighbor_offsets& offsets = Neighbor_offsets())
{
  CGAL_precondition(hint.empty() || hint.size() == points.size());
  if (std::find(present.begin(), present.end(), 0) == present.end())
    return all_indices(points.size());
  Array<Index> sites;
  for (Index i = 0; i < Index(points.size()); ++i)
    if (present[i])
      sites.push_back(i);
  const Point_tree tree(points, sites.begin(), sites.end(), ConcurrencyTag());
  Array<Index> nearest(points.size());
  for_each_index<ConcurrencyTag>(
    points.size(),
    [&](std::size_t i) {
      if (present[i])
        nearest[i] = Index(i);
      else if (!offsets.first_present(Index(i), 1, [&](Index p) { return present[p] != 0; }, &nearest[i]))
      {
        CGAL_assertion(hint.empty() || present[hint[i]]);
        nearest[i] = hint.empty() ? tree.nearest_one(Index(i)) : tree.nearest_before(Index(i), hint[i]);
      }
    },
    [](std::size_t) { return true; });
  return nearest;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NEAREST_PRESENT_POINTS_H
