// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Each point's nearest neighbours as offsets of one byte in the kd order,
// from which a search among the present points can often be answered
// without a tree.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NEIGHBOR_OFFSETS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NEIGHBOR_OFFSETS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The first neighbours of each point, at most 16 of its k nearest, each as
// its index minus the point's, while that fits in a signed byte, as in kd
// order most do: a byte a neighbour where the table takes four, and 16
// bytes a point at most whatever k. The present points among a prefix of a
// point's neighbours, in that order, are its nearest present points,
// exactly, whatever the points present. Searches need at most four, which
// 16 neighbours hold while about a quarter of them are present. With k =
// 10, on 1,000,000 lion samples kept to 10%, they answered 23% of the
// elimination's searches anew and 72% of the relocation's searches for the
// nearest present point (8.5% and 44% on the 2 mm replica of the paper's
// first experiment).
class Neighbor_offsets
{
public:
  static constexpr unsigned int most_columns = 16;

  Neighbor_offsets() = default;

  // From `knn`, the k nearest neighbours of each point nearest first (those
  // of point i at knn[i * k]); in parallel with CGAL::Parallel_tag.
  template <typename ConcurrencyTag = CGAL::Sequential_tag>
  Neighbor_offsets(const Array<Index>& knn, unsigned int k, ConcurrencyTag = ConcurrencyTag())
    : m_columns((std::min)(k, most_columns)), m_offsets(k == 0 ? 0 : knn.size() / k * m_columns, beyond)
  {
    for_each_index<ConcurrencyTag>(
      k == 0 ? 0 : knn.size() / k,
      [&](std::size_t i) {
        for (std::size_t j = 0; j < m_columns; ++j)
        {
          const std::int64_t offset = std::int64_t(knn[i * k + j]) - std::int64_t(i);
          if (offset <= beyond || offset > std::numeric_limits<std::int8_t>::max())
            break;
          m_offsets[i * m_columns + j] = std::int8_t(offset);
        }
      },
      [](std::size_t) { return true; });
  }

  // Writes to `first` the first `count` neighbours of `i` for which
  // `is_present` holds, nearest first, and returns true, when they are
  // among its first neighbours before the first whose offset does not fit;
  // returns false otherwise, `first` then holding nothing of use.
  template <typename IsPresent>
  bool first_present(Index i, std::size_t count, const IsPresent& is_present, Index* first) const
  {
    if (m_offsets.empty())
      return false;
    const std::int8_t* row = m_offsets.data() + std::size_t(i) * m_columns;
    std::size_t found = 0;
    for (std::size_t j = 0; j < m_columns && found < count && row[j] != beyond; ++j)
    {
      const Index neighbor = Index(std::int64_t(i) + row[j]);
      if (is_present(neighbor))
        first[found++] = neighbor;
    }
    return found == count;
  }

private:
  // the first offset that does not fit, and those after it
  static constexpr std::int8_t beyond = std::numeric_limits<std::int8_t>::min();
  unsigned int m_columns = 0;
  Array<std::int8_t> m_offsets;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NEIGHBOR_OFFSETS_H
