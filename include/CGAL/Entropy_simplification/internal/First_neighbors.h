// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What an elimination that starts with every point present keeps of the k
// nearest neighbours of each point, once their table is freed.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FIRST_NEIGHBORS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FIRST_NEIGHBORS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The first neighbours of each point as offsets (see Neighbor_offsets), and
// the first `count` of those points whose offsets do not hold that many, in
// columns: with them, every point's first `count` neighbours are known.
// Columns for every point took 12 bytes a point for 3 neighbours, built
// while the neighbour table was still held, which was the program's peak of
// memory on 10,000,000 lion samples (1,441,812 KB; 1,422,228 KB with the
// columns of the missed points alone, the peak then the entropies'). The
// offsets miss the first 3 neighbours of 13% of 1,000,000 lion samples, and
// of 49% and 56% of the replicas of the paper's first experiment.
struct First_neighbors
{
  Neighbor_offsets offsets;
  std::size_t count = 0;
  Array<Index> missed;  // the points the offsets miss, in index order
  Array<Index> columns; // the first `count` neighbours of missed[r] at columns[r * count]

  // Writes to `first`, which has room for them, the first `count`
  // neighbours of `i`, nearest first.
  void first_of(Index i, Index* first) const
  {
    if (offsets.first_present(i, count, [](Index) { return true; }, first))
      return;
    const auto r = std::lower_bound(missed.begin(), missed.end(), i);
    CGAL_assertion(r != missed.end() && *r == i);
    std::copy_n(columns.begin() + (r - missed.begin()) * std::ptrdiff_t(count), count, first);
  }

  // Frees the columns, once no elimination is to start from them: the
  // offsets alone stay.
  void release_columns()
  {
    count = 0;
    Array<Index>().swap(missed);
    Array<Index>().swap(columns);
  }
};

// The first neighbours that `knn`, the k nearest neighbours of each point
// nearest first (those of point i at knn[i * k]), gives of each point,
// `count` of them (see First_neighbors); none when `count` is 0 or above k.
template <typename ConcurrencyTag>
First_neighbors first_neighbors(const Array<Index>& knn, unsigned int k, std::size_t count)
{
  if (count == 0 || count > k)
    return {};
  const Index n = Index(knn.size() / k);
  First_neighbors first{ Neighbor_offsets(knn, k, ConcurrencyTag()), count, {}, {} };
  Array<Index> held(count);
  const auto offsets_miss = [&](Index i) {
    return !first.offsets.first_present(i, count, [](Index) { return true; }, held.data());
  };
  // counted first, so that the columns take no more room than they fill
  std::size_t missed_count = 0;
  for (Index i = 0; i < n; ++i)
    missed_count += std::size_t(offsets_miss(i));
  first.missed.reserve(missed_count);
  first.columns.reserve(missed_count * count);
  for (Index i = 0; i < n; ++i)
    if (offsets_miss(i))
    {
      first.missed.push_back(i);
      first.columns.insert(first.columns.end(), knn.begin() + std::ptrdiff_t(i) * k,
                           knn.begin() + std::ptrdiff_t(i) * k + std::ptrdiff_t(count));
    }
  return first;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FIRST_NEIGHBORS_H
