// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reorders a point range after a progressive removal.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ORDER_BY_REMOVAL_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ORDER_BY_REMOVAL_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <iterator>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The iterators of a range, by position.
template <typename Range>
Array<typename Range::iterator> iterators_of(Range& range)
{
  Array<typename Range::iterator> result;
  for (auto it = range.begin(); it != range.end(); ++it)
    result.push_back(it);
  return result;
}

// Moves the elements of a range, given by `at` (its iterators by position),
// so that the kept elements come first in their input order, followed by the
// removed ones, the last removed first. Then the first m elements, for any m
// from the number kept to the size, are what remained when m points were
// left. `removed` holds input positions in removal order. Only moves
// elements: the range stays a permutation of itself. Returns the position of
// the first removed element.
template <typename ConcurrencyTag, typename Iterator>
std::size_t order_by_removal(const Array<Iterator>& at, const Array<Index>& removed)
{
  const std::size_t n = at.size();
  Array<char> is_removed(n, 0);
  for (Index i : removed)
    is_removed[i] = 1;

  // source[j]: the input position of the element that goes to position j
  Array<Index> source;
  source.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (!is_removed[i])
      source.push_back(Index(i));
  const std::size_t kept = source.size();
  source.insert(source.end(), removed.rbegin(), removed.rend());

  // Moved out in their new order, then back: the reads are scattered, the
  // writes are not, and the moves either way are independent of each other
  // (the moves out too, when the elements can be constructed first).
  using Value = typename std::iterator_traits<Iterator>::value_type;
  Array<Value> moved;
  if constexpr (std::is_default_constructible<Value>::value)
  {
    moved.resize(n);
    for_each_index<ConcurrencyTag>(
      n, [&](std::size_t j) { moved[j] = std::move(*at[source[j]]); }, [](std::size_t) { return true; });
  }
  else
  {
    moved.reserve(n);
    for (Index s : source)
      moved.push_back(std::move(*at[s]));
  }
  for_each_index<ConcurrencyTag>(
    n, [&](std::size_t j) { *at[j] = std::move(moved[j]); }, [](std::size_t) { return true; });
  return kept;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_ORDER_BY_REMOVAL_H
