// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the default mode's two eliminations share: the points, the field
// computed from their neighbours, and which of them are present.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DEFAULT_MODE_ENGINE_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DEFAULT_MODE_ENGINE_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Default_mode_terms.h>
#include <CGAL/Entropy_simplification/internal/Elimination_field.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Neighbor_offsets.h>

#include <cstddef>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The base of Coverage_elimination and Weighted_elimination, every point
// present at first.
class Default_mode_engine
{
public:
  // Computes the field from the k nearest neighbours of every point, and
  // keeps the first neighbours the elimination asked for.
  // `progress` receives the fraction done, on the calling thread; returns
  // false when it asked to stop.
  template <typename ConcurrencyTag, typename Progress>
  bool initialize(const Progress& progress)
  {
    Array<Index> knn;
    return nearest_neighbors_of_all<ConcurrencyTag>(m_points, m_k, knn, [&](double f) { return progress(0.5 * f); }) &&
           compute_elimination_field<ConcurrencyTag>(m_points, m_k, m_options, m_terms, std::move(knn),
                                                     m_first_neighbors_kept, m_first_neighbors, m_field,
                                                     [&](double f) { return progress(0.5 + 0.5 * f); });
  }

  bool is_present(Index i) const { return m_present[i] != 0; }
  // The normals of the points `subset`, as the field estimated them.
  template <typename ConcurrencyTag>
  Array<Working_vector> normals_of(const Array<Index>& subset) const
  {
    return estimate_normals<ConcurrencyTag>(m_points, subset, m_k, m_options.normal_estimation);
  }
  const Elimination_field& field() const { return m_field; }
  // Each point's nearest present point after the last run, itself when
  // present (ties by input position), when the elimination followed them
  // for every point, or nothing; taken once. Those of a run the callback
  // stopped include the removals of its last round that it did not report.
  Array<Index> take_nearest_present() { return std::move(m_nearest_present); }
  // The offsets of each point's first neighbours (see Neighbor_offsets),
  // kept through the runs for the searches of the relocation, when
  // initialize() kept any; taken once.
  Neighbor_offsets take_neighbor_offsets() { return std::move(m_first_neighbors.offsets); }
  // Frees what initialize() kept of the first neighbours, once no run is
  // to follow. A run that removed nothing keeps their columns for the next,
  // which then follows them rather than searching for every point's nearest
  // present points.
  void release_first_neighbors() { m_first_neighbors = First_neighbors(); }

protected:
  // `first_neighbors_kept`: how many of each point's nearest neighbours
  // initialize() keeps (see m_first_neighbors).
  Default_mode_engine(const Indexed_points& points, unsigned int k, const Options& options,
                      const Default_mode_terms& terms, std::size_t first_neighbors_kept = 0)
    : m_points(points), m_k(k), m_options(options), m_terms(terms), m_present(points.size(), 1),
      m_count(points.size()), m_first_neighbors_kept(first_neighbors_kept)
  {}

  const Indexed_points& m_points;
  const unsigned int m_k;
  const Options m_options;
  const Default_mode_terms m_terms;
  Elimination_field m_field;
  Array<char> m_present;
  std::size_t m_count;
  // the first neighbours of each point, which initialize() kept for an
  // elimination that starts with every point present: its columns, empty
  // once it took them, and their offsets, which serve any present points
  const std::size_t m_first_neighbors_kept;
  First_neighbors m_first_neighbors;
  Array<Index> m_nearest_present; // see take_nearest_present
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DEFAULT_MODE_ENGINE_H
