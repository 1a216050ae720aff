// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default mode: weighted sample elimination with an interaction radius
// that shrinks where the entropy of normals marks a feature.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_WEIGHTED_ELIMINATION_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_WEIGHTED_ELIMINATION_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Elimination_field.h>
#include <CGAL/Entropy_simplification/internal/Feature_field.h>
#include <CGAL/Entropy_simplification/internal/Indexed_heap.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// One stage of the elimination: from `present` points down to `target`,
// with the radius of Yuksel's weighted sample elimination (2015) for
// `target` points on the area, and his weight limiting.
struct Elimination_stage
{
  std::size_t target;
  double radius;
  double limit;
};

// The stages halve the number of points, the last one reaching the target:
// each stage's radius suits its own count, and every stage's result is a
// subset of the previous one, so the elimination is progressive.
inline Elimination_stage next_stage(std::size_t present, std::size_t target, double effective_area)
{
  Elimination_stage stage;
  stage.target = (std::max)(target, (present + 1) / 2);
  stage.radius = std::sqrt(effective_area / (2. * std::sqrt(3.) * double(stage.target)));
  stage.limit = stage.radius * 0.65 * (1. - std::pow(double(stage.target) / double(present), 1.5));
  return stage;
}

// The weight of a pair, in units of 2^-40 so that sums and differences of
// weights are exact whatever their order: (1 - d / (2 r s))^8 within 2 r s,
// s the mean of the two points' scales, d not below the limit times s.
inline std::int64_t pair_weight(const Working_point& a, const Working_point& b, double scale_a, double scale_b,
                                const Elimination_stage& stage)
{
  const double s = (scale_a + scale_b) / 2.;
  const double reach = 2. * stage.radius * s;
  const double d = std::sqrt(squared_distance(a, b));
  if (!(d < reach))
    return 0;
  const double w = 1. - (std::max)(d, stage.limit * s) / reach;
  const double w2 = w * w, w4 = w2 * w2;
  return std::llround(w4 * w4 * 1099511627776.);
}

// The elimination on the present points. Each stage gathers, for each point,
// the others within its reach, sums their weights into the point's weight,
// and removes the point of greatest weight (ties: lowest input position),
// subtracting its weight from its neighbours', until the stage's target.
class Weighted_elimination
{
public:
  Weighted_elimination(const Indexed_points& points, unsigned int k, const Options& options)
    : m_points(points), m_k(k), m_options(options), m_present(points.size(), 1), m_count(points.size())
  {}

  // Computes the field from the k nearest neighbours of every point, and
  // from those of every `coarse_stride`-th point among these points.
  // `progress` receives the fraction done, on the calling thread; returns
  // false when it asked to stop.
  template <typename ConcurrencyTag, typename Progress>
  bool initialize(const Progress& progress)
  {
    const std::size_t n = m_points.size();
    std::vector<Index> knn;
    { // the tree goes before the field is computed
      const std::vector<Index> all = all_indices(n);
      const Point_tree tree(m_points, all.begin(), all.end(), ConcurrencyTag());
      if (!nearest_neighbor_table<ConcurrencyTag>(tree, all, m_k, knn, [&](std::size_t done) {
            return progress(0.5 * double(done) / double(n));
          }))
        return false;
    }
    std::vector<Index> coarse;
    for (std::size_t i = 0; i < n; i += coarse_stride)
      coarse.push_back(Index(i));
    if (!compute_elimination_field<ConcurrencyTag>(
          m_points, coarse, m_k, m_options, [&](Index i) { return &knn[std::size_t(i) * m_k]; }, m_field,
          [&](double f) { return progress(0.5 + 0.5 * f); }))
      return false;
    return true;
  }

  bool is_present(Index i) const { return m_present[i] != 0; }
  const Working_vector& normal(Index i) const { return m_field.normals[i]; }
  const Elimination_field& field() const { return m_field; }

  // Removes points down to `target`, calling `removed(i)` after each removal;
  // stops early, returning false, when it returns false.
  template <typename ConcurrencyTag, typename Removed>
  bool remove_down_to(std::size_t target, const Removed& removed)
  {
    while (m_count > target)
    {
      const Elimination_stage stage = next_stage(m_count, target, m_field.effective_area);
      gather_neighbors<ConcurrencyTag>(stage);
      if (!eliminate(stage, removed))
        return false;
    }
    // the relocation that follows needs none of the elimination's memory
    std::vector<std::size_t>().swap(m_first);
    std::vector<Index>().swap(m_neighbors);
    std::vector<std::int64_t>().swap(m_weight);
    return true;
  }

private:
  // For each present point, the present points within its reach, in CSR
  // form, and its weight. The points are taken by blocks, each gathered in
  // parallel then appended in index order, so that the lists in the making
  // never hold more than a block.
  template <typename ConcurrencyTag>
  void gather_neighbors(const Elimination_stage& stage)
  {
    std::vector<Index> present;
    for (Index i = 0; i < Index(m_points.size()); ++i)
      if (is_present(i))
        present.push_back(i);
    Point_tree tree(m_points, present.begin(), present.end(), ConcurrencyTag());
    tree.record_largest_scales(m_field.scale);

    m_first.assign(m_points.size() + 1, 0);
    m_neighbors.clear();
    m_weight.assign(m_points.size(), 0);
    std::vector<std::vector<Index> > lists((std::min)(present.size(), gather_block));
    for (std::size_t first = 0; first < present.size(); first += gather_block)
    {
      const std::size_t count = (std::min)(gather_block, present.size() - first);
      for_each_index<ConcurrencyTag>(
        count,
        [&](std::size_t r) {
          const Index i = present[first + r];
          thread_local std::vector<Index> inside;
          tree.within_reach(m_points.points[i], stage.radius, m_field.scale[i], m_field.scale, inside);
          lists[r].clear();
          for (Index j : inside)
            if (const std::int64_t w = j != i ? weight(i, j, stage) : 0)
            {
              lists[r].push_back(j);
              m_weight[i] += w;
            }
        },
        [](std::size_t) { return true; });
      for (std::size_t r = 0; r < count; ++r)
      {
        m_first[present[first + r] + 1] = lists[r].size();
        m_neighbors.insert(m_neighbors.end(), lists[r].begin(), lists[r].end());
      }
      // the first block predicts the whole, so that the array rarely grows
      // by doubling, which would hold twice the memory at the peak
      if (first == 0)
        m_neighbors.reserve(std::size_t(1.05 * double(m_neighbors.size()) * double(present.size()) / double(count)));
    }
    // counts to offsets: the lists were appended in index order
    for (std::size_t i = 0; i < m_points.size(); ++i)
      m_first[i + 1] += m_first[i];
  }

  template <typename Removed>
  bool eliminate(const Elimination_stage& stage, const Removed& removed)
  {
    std::vector<Indexed_heap::Entry> entries;
    entries.reserve(m_count);
    for (Index i = 0; i < Index(m_points.size()); ++i)
      if (is_present(i))
        entries.push_back(Indexed_heap::Entry{ -double(m_weight[i]), m_points.input_position[i], i });
    Indexed_heap heap(std::move(entries), m_points.size());

    while (m_count > stage.target)
    {
      const Index p = heap.top().id;
      heap.pop();
      m_present[p] = 0;
      --m_count;
      for (std::size_t e = m_first[p]; e < m_first[p + 1]; ++e)
      {
        const Index j = m_neighbors[e];
        if (!is_present(j))
          continue;
        m_weight[j] -= weight(p, j, stage);
        heap.update(j, -double(m_weight[j]));
      }
      if (!removed(p))
        return false;
    }
    return true;
  }

  std::int64_t weight(Index a, Index b, const Elimination_stage& stage) const
  {
    return pair_weight(m_points.points[a], m_points.points[b], m_field.scale[a], m_field.scale[b], stage);
  }

  const Indexed_points& m_points;
  const unsigned int m_k;
  const Options m_options;
  Elimination_field m_field;
  std::vector<char> m_present;
  std::size_t m_count;
  static constexpr std::size_t gather_block = std::size_t(1) << 15;
  // CSR offsets of each point's neighbours: 64-bit, as dense clouds can hold
  // more than 2^32 pairs within reach
  std::vector<std::size_t> m_first;
  std::vector<Index> m_neighbors;   // CSR neighbours
  std::vector<std::int64_t> m_weight;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_WEIGHTED_ELIMINATION_H
