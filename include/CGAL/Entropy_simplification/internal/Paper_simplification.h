// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's progressive simplification (Eq. 1-5) with exact updates.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_PAPER_SIMPLIFICATION_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_PAPER_SIMPLIFICATION_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Decremental_knn.h>
#include <CGAL/Entropy_simplification/internal/Indexed_heap.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>
#include <CGAL/Entropy_simplification/internal/normal_angle_entropy.h>
#include <CGAL/Entropy_simplification/internal/prefetch.h>

#include <cstddef>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The state of the paper's method on the present points: for each, its k
// nearest neighbours, its normal angle and its importance, kept equal to what
// a from-scratch computation on the present points gives.
//
// Removing p changes the neighbourhood, hence the normal and the angle, of the
// points that had p among their k nearest neighbours (R1), and the importance
// of R1 and of every point that has a point of R1 among its neighbours. The
// paper's "first and second rings" read as p's own neighbours would miss
// some of these points and update others needlessly.
class Paper_simplification
{
public:
  Paper_simplification(const Indexed_points& points, unsigned int k, const Options& options,
                       const Working_vector& reference_normal)
    : m_points(points),
      m_k(k),
      m_options(options),
      m_reference(reference_normal),
      m_knn(points, k),
      m_angles(points.size()),
      m_mark(points.size(), 0)
  {}

  // Computes every neighbourhood, normal, angle and importance. `progress`
  // receives the fraction done, on the calling thread; returns false when it
  // asked to stop.
  template <typename ConcurrencyTag, typename Progress>
  bool initialize(const Progress& progress)
  {
    const std::size_t n = m_points.size();
    // The neighbour search costs about as much as the two other passes.
    if (!m_knn.template initialize<ConcurrencyTag>([&progress](double f) { return progress(0.5 * f); }))
      return false;
    if (!for_each_index<ConcurrencyTag>(
          n, [&](std::size_t i) { refresh_angle(Index(i)); }, share_of_progress(n, 0.5, 0.3, progress)))
      return false;

    Array<Indexed_heap::Entry> entries(n);
    if (!for_each_index<ConcurrencyTag>(
          n,
          [&](std::size_t i) {
            entries[i] = Indexed_heap::Entry{ heap_key(Index(i)), m_points.input_position[i], Index(i) };
          },
          share_of_progress(n, 0.8, 0.2, progress)))
      return false;
    m_heap = Indexed_heap(std::move(entries), n);
    return true;
  }

  bool is_present(Index i) const { return m_knn.is_present(i); }

  // Removes points down to `target`, calling `removed(i)` after each
  // removal; stops early, returning false, when it returns false.
  template <typename ConcurrencyTag, typename Removed>
  bool remove_down_to(std::size_t target, const Removed& removed)
  {
    while (m_heap.size() > target)
      if (!removed(remove_next()))
        return false;
    return true;
  }

  // The normal of a present point, estimated on its present neighbours.
  Working_vector normal(Index i) const
  {
    return neighborhood_normal(m_points, i, m_knn.neighbors(i), m_k, m_options.normal_estimation);
  }

  // The normals of the points `subset`, as `normal` gives them.
  template <typename ConcurrencyTag>
  Array<Working_vector> normals_of(const Array<Index>& subset) const
  {
    Array<Working_vector> normals(subset.size());
    for_each_index<ConcurrencyTag>(
      subset.size(), [&](std::size_t r) { normals[r] = normal(subset[r]); }, [](std::size_t) { return true; });
    return normals;
  }

  // Eq. 5 over a present point and its present neighbours.
  double importance(Index i) const
  {
    const Index* neighbors = m_knn.neighbors(i);
    return angle_entropy(m_k + 1, [&](std::size_t j) -> const Angle_term& {
      return m_angles[j == 0 ? i : neighbors[j - 1]];
    });
  }

private:
  // Removes the least important point (by the chosen order, ties broken by
  // input position) and updates the others; returns the removed point.
  Index remove_next()
  {
    const Index p = m_heap.top().id;
    m_heap.pop();
    m_knn.remove(p, m_changed);
    // the scattered data of the loops below is loaded ahead, so that its
    // cache misses overlap (see prefetch.h)
    for (Index q : m_changed)
      for (unsigned int j = 0; j < m_k; ++j)
        prefetch(&m_points.points[m_knn.neighbors(q)[j]]);
    for (Index q : m_changed)
      refresh_angle(q);

    ++m_epoch;
    m_refreshed.clear();
    auto refresh_importance = [this](Index r) {
      if (m_mark[r] == m_epoch)
        return;
      m_mark[r] = m_epoch;
      m_refreshed.push_back(r);
    };
    for (Index q : m_changed)
    {
      refresh_importance(q);
      m_knn.for_each_reverse_neighbor(q, refresh_importance);
    }
    // the keys first, then the heap: the keys' reads are independent, so
    // the processor overlaps their cache misses, which it does not across
    // the branches of the sifts in between
    for (Index r : m_refreshed)
      prefetch(m_knn.neighbors(r));
    m_keys.resize(m_refreshed.size());
    for (std::size_t r = 0; r < m_refreshed.size(); ++r)
      m_keys[r] = heap_key(m_refreshed[r]);
    for (std::size_t r = 0; r < m_refreshed.size(); ++r)
      m_heap.update(m_refreshed[r], m_keys[r]);
    return p;
  }

  void refresh_angle(Index i) { m_angles[i] = make_angle_term(normal_angle(normal(i), m_reference)); }

  // The heap pops its least key first.
  double heap_key(Index i) const
  {
    const double h = importance(i);
    return m_options.removal_order == Removal_order::lowest_entropy_first ? h : -h;
  }

  const Indexed_points& m_points;
  const unsigned int m_k;
  const Options m_options;
  const Working_vector m_reference;
  Decremental_knn m_knn;
  Array<Angle_term> m_angles;
  Indexed_heap m_heap{ {}, 0 };
  Array<Index> m_changed;
  Array<Index> m_refreshed; // the points whose importance a removal changed
  Array<double> m_keys;     // and their new keys
  Array<Index> m_mark; // removal at which a point's importance was last refreshed
  Index m_epoch = 0;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_PAPER_SIMPLIFICATION_H
