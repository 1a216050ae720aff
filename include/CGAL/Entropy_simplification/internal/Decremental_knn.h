// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact k nearest neighbours of every point of a set from which points are
// removed one at a time.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DECREMENTAL_KNN_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DECREMENTAL_KNN_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>
#include <CGAL/Entropy_simplification/internal/prefetch.h>

#include <CGAL/Entropy_simplification/internal/Point_tree.h>

#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <unordered_map>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The neighbour order of a point q: the other present points sorted by
// squared distance to q, ties broken by input position. Its first k entries
// are the k nearest neighbours of q, which is what a from-scratch computation
// on the present points gives.
//
// Each point keeps a candidate list: an exact prefix of its neighbour order
// when it was filled, of up to `capacity` points. Removing a point keeps
// every candidate list a prefix once the removed points are skipped, so a
// list needs the Kd tree again only when fewer than k candidates are left.
// Reverse lists record, for each point s, the points that have s among their
// k nearest neighbours: removing s changes exactly their neighbourhoods.
//
// Requires at least k + 1 present points at all times.
class Decremental_knn
{
  using Count = std::uint16_t;

public:
  static constexpr unsigned int largest_k = 1000;

  Decremental_knn(const Indexed_points& points, unsigned int k)
    : m_points(points),
      m_k(k),
      m_capacity(2 * k),
      m_block(k + k / 2 + 2),
      m_count(points.size(), 0),
      m_present(points.size(), 1),
      m_reverse_count(points.size(), 0)
  {
    if (k == 0 || k > largest_k)
      throw std::invalid_argument("k must lie in [1, 1000]");
    if (points.size() < std::size_t(k) + 1)
      throw std::invalid_argument("k nearest neighbours need at least k + 1 points");
    build_tree(all_indices(points.size()));
  }

  bool is_present(Index i) const { return m_present[i] != 0; }

  // The k nearest present neighbours of `i`, nearest first.
  const Index* neighbors(Index i) const { return &m_candidates[std::size_t(i) * m_capacity]; }

  // Fills every candidate list, then the reverse lists, which count for 80%
  // and 20% of the fraction done that `progress` receives between blocks of
  // points, on the calling thread; returns false when it asked to stop, and
  // throws std::invalid_argument when two points are too near to be told
  // apart (see too_near_to_tell_apart). The lists' arrays, large with a
  // large k (1.3 GB at 300,000 points and k = 300), grow 4M entries at a
  // time, so that a stop is seen meanwhile.
  template <typename ConcurrencyTag, typename Progress>
  bool initialize(const Progress& progress)
  {
    const std::size_t n = m_points.size();
    const std::size_t part = (std::size_t(1) << 22) / m_capacity + 1;
    reserve_untouched(m_candidates, n * m_capacity);
    reserve_untouched(m_reverse, n * m_block);
    std::atomic<bool> too_near(false);
    const auto fill_progress = share_of_progress(n, 0., 0.8, progress);
    const bool filled = for_each_index_growing<ConcurrencyTag>(
      n, part, [&](std::size_t points) { grow_touched(m_candidates, points * m_capacity); },
      [&](std::size_t i) {
        if (!fill_candidates(Index(i)))
          too_near.store(true, std::memory_order_relaxed);
      },
      [&](std::size_t done) { return !too_near.load(std::memory_order_relaxed) && fill_progress(done); });
    if (too_near)
      throw points_too_near_to_tell_apart();
    return filled &&
           for_each_index_growing<CGAL::Sequential_tag>(
             n, part, [&](std::size_t points) { grow_touched(m_reverse, points * m_block); }, [](std::size_t) {},
             share_of_progress(n, 0.8, 0.1, progress)) &&
           for_each_index<CGAL::Sequential_tag>(
             n,
             [&](std::size_t q) {
               for (unsigned int j = 0; j < m_k; ++j)
                 add_reverse(neighbors(Index(q))[j], Index(q));
             },
             share_of_progress(n, 0.9, 0.1, progress));
  }

  // Removes `p` and writes to `changed` the present points that had `p`
  // among their k nearest neighbours; each of them now has a new k-th one.
  void remove(Index p, Array<Index>& changed)
  {
    m_present[p] = 0;
    m_tree->remove(p);
    if (2 * --m_present_count < m_tree_size)
      rebuild_tree();
    // the lists this removal edits are scattered: their loads are started
    // together, so that their cache misses overlap
    for (unsigned int j = 0; j < m_k; ++j)
      prefetch_list(m_reverse, neighbors(p)[j], m_block);
    changed.clear();
    for_each_reverse_neighbor(p, [&](Index q) {
      changed.push_back(q);
      prefetch_list(m_candidates, q, m_capacity);
    });
    for (unsigned int j = 0; j < m_k; ++j)
      erase_reverse(neighbors(p)[j], p);
    clear_reverse(p);
    for (Index q : changed)
    {
      erase_candidate(q, p);
      if (m_count[q] < m_k)
      {
        // the points were told apart when the lists were first filled
        const bool apart = fill_candidates(q);
        CGAL_assertion(apart);
        CGAL_USE(apart);
      }
      add_reverse(neighbors(q)[m_k - 1], q);
    }
  }

  // Calls `f(r)` for each present point r that has `q` among its k nearest
  // neighbours.
  template <typename Function>
  void for_each_reverse_neighbor(Index q, const Function& f) const
  {
    const Index* block = &m_reverse[std::size_t(q) * m_block];
    const std::size_t count = m_reverse_count[q];
    for (std::size_t j = 0; j < (std::min)(count, m_block); ++j)
      f(block[j]);
    if (count > m_block)
      for (Index r : m_overflow.at(q))
        f(r);
  }

private:
  // A deleted point leaves the boxes of the tree's nodes as they were, so a
  // search in a tree whose points are mostly deleted visits many empty
  // leaves. Rebuilding it each time half its points are gone costs at most
  // twice the first build.
  void build_tree(const Array<Index>& indices)
  {
    m_tree = std::make_unique<Point_tree>(m_points, indices.begin(), indices.end());
    m_tree_size = m_present_count = indices.size();
  }

  void rebuild_tree()
  {
    Array<Index> present;
    present.reserve(m_present_count);
    for (Index i = 0; i < Index(m_points.size()); ++i)
      if (is_present(i))
        present.push_back(i);
    build_tree(present);
  }

  // Starts loading the list of `i` in `lists`, `size` entries per point
  // (its two ends: a list spans one or two cache lines at k = 10).
  static void prefetch_list(const Array<Index>& lists, Index i, std::size_t size)
  {
    prefetch(&lists[std::size_t(i) * size]);
    prefetch(&lists[std::size_t(i) * size + size - 1]);
  }

  // Sets the candidate list of `q` to the first `capacity` entries of its
  // neighbour order (or all of them when fewer points are present); returns
  // false, the list unset, when a point is too near `q` to be told apart
  // from it (see too_near_to_tell_apart).
  bool fill_candidates(Index q)
  {
    thread_local Array<Neighbor> best;
    if (!m_tree->nearest_apart(q, m_capacity, best))
      return false;
    Index* list = &m_candidates[std::size_t(q) * m_capacity];
    for (std::size_t j = 0; j < best.size(); ++j)
      list[j] = best[j].id;
    m_count[q] = Count(best.size());
    return true;
  }

  // Erases `p`, one of the k nearest neighbours of `q`, from the candidates of
  // `q`, with the spare candidates (beyond the k-th) removed since the list
  // was filled: the first k entries are then present again, and the list is
  // a prefix of the neighbour order of `q` among the present points.
  void erase_candidate(Index q, Index p)
  {
    Index* list = &m_candidates[std::size_t(q) * m_capacity];
    Index* end = list + m_count[q];
    Index* position = std::find(list, list + m_k, p);
    CGAL_assertion(position != list + m_k);
    std::copy(position + 1, end, position);
    end = std::remove_if(list + m_k - 1, end - 1, [this](Index i) { return !is_present(i); });
    m_count[q] = Count(end - list);
  }

  // Reverse lists: the first `m_block` entries of a point inline, the rare
  // others in an overflow vector.
  void add_reverse(Index s, Index q)
  {
    const std::size_t count = m_reverse_count[s]++;
    if (count < m_block)
      m_reverse[std::size_t(s) * m_block + count] = q;
    else
      m_overflow[s].push_back(q);
  }

  // Replaces `q` by the last entry.
  void erase_reverse(Index s, Index q)
  {
    Index* block = &m_reverse[std::size_t(s) * m_block];
    const std::size_t count = m_reverse_count[s]--;
    Index* last = count > m_block ? &m_overflow[s].back() : block + count - 1;
    Index* position = std::find(block, block + (std::min)(count, m_block), q);
    if (position == block + (std::min)(count, m_block))
      position = &*std::find(m_overflow[s].begin(), m_overflow[s].end(), q);
    *position = *last;
    if (count > m_block)
    {
      m_overflow[s].pop_back();
      if (m_overflow[s].empty())
        m_overflow.erase(s);
    }
  }

  void clear_reverse(Index s)
  {
    if (m_reverse_count[s] > m_block)
      m_overflow.erase(s);
    m_reverse_count[s] = 0;
  }

  const Indexed_points& m_points;
  const unsigned int m_k;
  const std::size_t m_capacity;
  const std::size_t m_block;
  std::unique_ptr<Point_tree> m_tree;
  std::size_t m_tree_size = 0;     // points the tree was built with
  std::size_t m_present_count = 0; // points present
  Array<Index> m_candidates; // m_capacity entries per point
  Array<Count> m_count;
  Array<char> m_present;
  Array<Index> m_reverse; // m_block entries per point
  Array<Index> m_reverse_count;
  std::unordered_map<Index, Array<Index> > m_overflow;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DECREMENTAL_KNN_H
