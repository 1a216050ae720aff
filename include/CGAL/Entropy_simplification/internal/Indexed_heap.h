// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mutable min-heap of point indices.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_HEAP_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_HEAP_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <limits>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// A binary min-heap of the indices [0, n), ordered by (key, tie), where `tie`
// is unique (an input position), so the top is always unique. Keys are stored
// in the heap itself, which keeps a sift within a few cache lines; `update`
// moves an index up or down after its key changed.
class Indexed_heap
{
public:
  struct Entry
  {
    double key;
    Index tie;
    Index id;
  };

  // The entries' ids must be distinct and below `id_count`.
  Indexed_heap(Array<Entry> entries, std::size_t id_count)
    : m_heap(std::move(entries)), m_position(id_count, none)
  {
    for (std::size_t i = 0; i < m_heap.size(); ++i)
      m_position[m_heap[i].id] = Index(i);
    for (std::size_t i = m_heap.size() / 2; i-- > 0;)
      sift_down(i);
  }

  std::size_t size() const { return m_heap.size(); }
  const Entry& top() const { return m_heap.front(); }
  bool contains(Index id) const { return m_position[id] != none; }

  void pop()
  {
    m_position[m_heap.front().id] = none;
    if (m_heap.size() > 1)
      place(0, m_heap.back());
    m_heap.pop_back();
    if (!m_heap.empty())
      sift_down(0);
  }

  void update(Index id, double key)
  {
    CGAL_precondition(contains(id));
    const std::size_t i = m_position[id];
    const double old = m_heap[i].key;
    m_heap[i].key = key;
    if (key < old)
      sift_up(i);
    else if (old < key)
      sift_down(i);
  }

private:
  static constexpr Index none = (std::numeric_limits<Index>::max)();

  static bool before(const Entry& a, const Entry& b)
  {
    return a.key < b.key || (a.key == b.key && a.tie < b.tie);
  }

  void place(std::size_t i, const Entry& e)
  {
    m_heap[i] = e;
    m_position[e.id] = Index(i);
  }

  void sift_up(std::size_t i)
  {
    const Entry e = m_heap[i];
    while (i > 0)
    {
      const std::size_t parent = (i - 1) / 2;
      if (!before(e, m_heap[parent]))
        break;
      place(i, m_heap[parent]);
      i = parent;
    }
    place(i, e);
  }

  void sift_down(std::size_t i)
  {
    const Entry e = m_heap[i];
    const std::size_t n = m_heap.size();
    for (;;)
    {
      std::size_t child = 2 * i + 1;
      if (child >= n)
        break;
      if (child + 1 < n && before(m_heap[child + 1], m_heap[child]))
        ++child;
      if (!before(m_heap[child], e))
        break;
      place(i, m_heap[child]);
      i = child;
    }
    place(i, e);
  }

  Array<Entry> m_heap;
  Array<Index> m_position;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_INDEXED_HEAP_H
