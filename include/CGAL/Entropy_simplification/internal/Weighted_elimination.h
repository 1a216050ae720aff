// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default mode: weighted sample elimination with an interaction radius
// that shrinks where the entropy of normals marks a feature.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_WEIGHTED_ELIMINATION_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_WEIGHTED_ELIMINATION_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Feature_field.h>
#include <CGAL/Entropy_simplification/internal/Indexed_heap.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// What the elimination needs of each point, computed once on the input from
// its k nearest neighbours: its normal, and the factor of its interaction
// radius (1 off features, smaller on them).
struct Elimination_field
{
  std::vector<Working_vector> normals;
  std::vector<double> scale;
  // the area the points sample, each point's share weighted by the density
  // its scale asks for (1 / scale^2)
  double effective_area = 0.;
};

// The entropy of the normals of each point's neighbourhood, `neighbors(i)`
// giving the k nearest neighbours of point `i` nearest first; the normals,
// estimated on each point and its neighbours, go to `normals`.
template <typename ConcurrencyTag, typename NeighborsOf, typename Progress>
bool estimate_normal_entropy(const Indexed_points& points, const std::vector<Index>& subset, unsigned int k,
                             Normal_estimation estimation, const NeighborsOf& neighbors,
                             std::vector<Working_vector>& normals, std::vector<double>& entropy,
                             const Progress& progress)
{
  const std::size_t m = subset.size();
  if (!for_each_index<ConcurrencyTag>(
        m,
        [&](std::size_t r) {
          const Index i = subset[r];
          const Index* near = neighbors(i);
          normals[i] = estimate_normal(estimation, k + 1, [&](std::size_t j) -> const Working_point& {
            return points.points[j == 0 ? i : near[j - 1]];
          });
        },
        [&](std::size_t done) { return progress(0.5 * double(done) / double(m)); }))
    return false;
  return for_each_index<ConcurrencyTag>(
    m,
    [&](std::size_t r) {
      const Index i = subset[r];
      const Index* near = neighbors(i);
      entropy[i] = normal_tensor_entropy(k + 1, [&](std::size_t j) -> const Working_vector& {
        return normals[j == 0 ? i : near[j - 1]];
      });
    },
    [&](std::size_t done) { return progress(0.5 + 0.5 * double(done) / double(m)); });
}

// The feature strength at a coarse scale, for every point: that of its
// nearest point of `coarse`, whose normals and entropies are computed among
// the coarse points only. Their neighbourhoods are wider, so that a smooth
// curvature that scanner noise hides at the fine scale shows there.
template <typename ConcurrencyTag>
std::vector<double> coarse_feature_strength(const Indexed_points& points, const std::vector<Index>& coarse,
                                            unsigned int k, Normal_estimation estimation)
{
  const std::size_t n = points.size();
  std::vector<double> strength(n, 0.);
  if (coarse.size() < std::size_t(k) + 1)
    return strength;
  const Point_tree tree(points, coarse.begin(), coarse.end());
  std::vector<Index> knn(coarse.size() * k);
  // the position of each coarse point in `coarse`, one past the end for the others
  std::vector<Index> slot(n, Index(coarse.size()));
  for (std::size_t r = 0; r < coarse.size(); ++r)
    slot[coarse[r]] = Index(r);
  for_each_index<ConcurrencyTag>(
    coarse.size(),
    [&](std::size_t r) {
      thread_local std::vector<Neighbor> best;
      tree.nearest(coarse[r], k, best);
      for (unsigned int j = 0; j < k; ++j)
        knn[r * k + j] = best[j].id;
    },
    [](std::size_t) { return true; });
  std::vector<Working_vector> normals(n, CGAL::NULL_VECTOR);
  std::vector<double> entropy(n, 0.);
  estimate_normal_entropy<ConcurrencyTag>(
    points, coarse, k, estimation, [&](Index i) { return &knn[std::size_t(slot[i]) * k]; }, normals, entropy,
    [](double) { return true; });
  std::vector<double> coarse_entropy;
  for (Index c : coarse)
    coarse_entropy.push_back(entropy[c]);
  const double floor = entropy_noise_floor(coarse_entropy);
  for_each_index<ConcurrencyTag>(
    n,
    [&](std::size_t i) {
      thread_local std::vector<Neighbor> nearest;
      Index c = Index(i);
      // a coarse point is its own nearest, which the search leaves out
      if (slot[i] == coarse.size())
      {
        tree.nearest(Index(i), 1, nearest);
        c = nearest.front().id;
      }
      strength[i] = feature_strength(entropy[c], floor);
    },
    [](std::size_t) { return true; });
  return strength;
}

// The field from the k nearest neighbours of each point, `neighbors(i)`
// giving them nearest first: normals estimated on each point and its
// neighbours; the feature strength the greater of that of the entropy of the
// normals of the same neighbourhood and that of the coarse scale.
template <typename ConcurrencyTag, typename NeighborsOf, typename Progress>
bool compute_elimination_field(const Indexed_points& points, const std::vector<Index>& coarse, unsigned int k,
                               const Options& options, const NeighborsOf& neighbors, Elimination_field& field,
                               const Progress& progress)
{
  const std::size_t n = points.size();
  std::vector<Index> all(n);
  for (std::size_t i = 0; i < n; ++i)
    all[i] = Index(i);
  field.normals.assign(n, CGAL::NULL_VECTOR);
  std::vector<double> entropy(n);
  if (!estimate_normal_entropy<ConcurrencyTag>(points, all, k, options.normal_estimation, neighbors, field.normals,
                                               entropy, progress))
    return false;
  const std::vector<double> coarse_strength =
    coarse_feature_strength<ConcurrencyTag>(points, coarse, k, options.normal_estimation);

  const double floor = entropy_noise_floor(entropy);
  std::vector<double> area(n), strength(n);
  double total_area = 0., feature_area = 0.;
  for (std::size_t i = 0; i < n; ++i)
  {
    // k points in a disc of the radius of the k-th neighbour
    area[i] = CGAL_PI * squared_distance(points.points[i], points.points[neighbors(Index(i))[k - 1]]) / double(k);
    strength[i] = (std::max)(feature_strength(entropy[i], floor), coarse_strength[i]);
    total_area += area[i];
    feature_area += area[i] * strength[i];
  }
  const double weight = budgeted_feature_weight(options.feature_weight, feature_area, total_area);
  const double typical_area = median(area);

  field.scale.resize(n);
  std::vector<double> weighted_area(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    field.scale[i] = interaction_scale(strength[i], weight) * density_scale(area[i], typical_area);
    weighted_area[points.input_position[i]] = area[i] / (field.scale[i] * field.scale[i]);
  }
  // summed in input order, so that the sum does not depend on the internal order
  field.effective_area = 0.;
  for (double a : weighted_area)
    field.effective_area += a;
  return true;
}

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

  template <typename ConcurrencyTag, typename Progress>
  bool initialize(const Progress& progress)
  {
    const std::size_t n = m_points.size();
    std::vector<Index> all(n);
    for (std::size_t i = 0; i < n; ++i)
      all[i] = Index(i);
    const Point_tree tree(m_points, all.begin(), all.end());
    std::vector<Index> knn(n * m_k);
    if (!for_each_index<ConcurrencyTag>(
          n,
          [&](std::size_t i) {
            thread_local std::vector<Neighbor> best;
            tree.nearest(Index(i), m_k, best);
            for (unsigned int j = 0; j < m_k; ++j)
              knn[i * m_k + j] = best[j].id;
          },
          [&](std::size_t done) { return progress(0.5 * double(done) / double(n)); }))
      return false;
    std::vector<Index> coarse;
    for (std::size_t i = 0; i < n; i += coarse_stride)
      coarse.push_back(Index(i));
    if (!compute_elimination_field<ConcurrencyTag>(
          m_points, coarse, m_k, m_options, [&](Index i) { return &knn[std::size_t(i) * m_k]; }, m_field,
          [&](double f) { return progress(0.5 + 0.5 * f); }))
      return false;
    m_largest_scale = *std::max_element(m_field.scale.begin(), m_field.scale.end());
    return true;
  }

  bool is_present(Index i) const { return m_present[i] != 0; }
  const Working_vector& normal(Index i) const { return m_field.normals[i]; }

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
    return true;
  }

  // Lloyd's relaxation restricted to the input points, `iterations` times:
  // each input point joins the cell of its nearest present point (ties by
  // input position), and each cell keeps the member nearest the cell's
  // centroid. Keeps the count; returns the pairs (point no longer present,
  // point present instead), both sets in input order.
  template <typename ConcurrencyTag>
  std::vector<std::pair<Index, Index> > relocate(int iterations)
  {
    const std::size_t n = m_points.size();
    const std::vector<char> before = m_present;
    std::vector<Index> by_input(n);
    for (Index i = 0; i < Index(n); ++i)
      by_input[m_points.input_position[i]] = i;

    std::vector<Index> cell(n);
    for (int iteration = 0; iteration < iterations; ++iteration)
    {
      std::vector<Index> present;
      for (Index i = 0; i < Index(n); ++i)
        if (is_present(i))
          present.push_back(i);
      const Point_tree tree(m_points, present.begin(), present.end());
      for_each_index<ConcurrencyTag>(
        n,
        [&](std::size_t i) {
          thread_local std::vector<Neighbor> nearest;
          if (is_present(Index(i)))
            cell[i] = Index(i);
          else
          {
            tree.nearest(Index(i), 1, nearest);
            cell[i] = nearest.front().id;
          }
        },
        [](std::size_t) { return true; });
      m_present = relocated(cell, by_input);
    }

    std::vector<Index> gone, come;
    for (Index position = 0; position < Index(n); ++position)
    {
      const Index i = by_input[position];
      if (before[i] && !is_present(i))
        gone.push_back(i);
      if (!before[i] && is_present(i))
        come.push_back(i);
    }
    std::vector<std::pair<Index, Index> > swaps;
    for (std::size_t j = 0; j < gone.size(); ++j)
      swaps.emplace_back(gone[j], come[j]);
    return swaps;
  }

private:
  // The member of each cell nearest its centroid; sums run in input order.
  std::vector<char> relocated(const std::vector<Index>& cell, const std::vector<Index>& by_input) const
  {
    const std::size_t n = m_points.size();
    std::vector<std::array<double, 4> > sum(n, { 0., 0., 0., 0. });
    for (Index i : by_input)
    {
      const Working_point& p = m_points.points[i];
      std::array<double, 4>& s = sum[cell[i]];
      s[0] += p.x();
      s[1] += p.y();
      s[2] += p.z();
      s[3] += 1.;
    }
    std::vector<Neighbor> best(n, Neighbor{ std::numeric_limits<double>::infinity(), 0, 0 });
    for (Index i : by_input)
    {
      const std::array<double, 4>& s = sum[cell[i]];
      const Working_point centroid(s[0] / s[3], s[1] / s[3], s[2] / s[3]);
      const Neighbor candidate{ squared_distance(m_points.points[i], centroid), m_points.input_position[i], i };
      if (candidate < best[cell[i]])
        best[cell[i]] = candidate;
    }
    std::vector<char> present(n, 0);
    for (Index i = 0; i < Index(n); ++i)
      if (is_present(i))
        present[best[i].id] = 1;
    return present;
  }

  // For each present point, the present points within its reach, in CSR form.
  template <typename ConcurrencyTag>
  void gather_neighbors(const Elimination_stage& stage)
  {
    std::vector<Index> present;
    for (Index i = 0; i < Index(m_points.size()); ++i)
      if (is_present(i))
        present.push_back(i);
    const Point_tree tree(m_points, present.begin(), present.end());

    std::vector<std::vector<Index> > lists(present.size());
    for_each_index<ConcurrencyTag>(
      present.size(),
      [&](std::size_t r) {
        const Index i = present[r];
        thread_local std::vector<Index> inside;
        // the reach of a pair is 2 r times the mean of the two scales
        tree.within(m_points.points[i], stage.radius * (m_field.scale[i] + m_largest_scale) * (1. + 1e-9), inside);
        for (Index j : inside)
          if (j != i && weight(i, j, stage) > 0)
            lists[r].push_back(j);
      },
      [](std::size_t) { return true; });

    m_first.assign(m_points.size() + 1, 0);
    for (std::size_t r = 0; r < present.size(); ++r)
      m_first[present[r] + 1] = Index(lists[r].size());
    for (std::size_t i = 0; i < m_points.size(); ++i)
      m_first[i + 1] += m_first[i];
    m_neighbors.resize(m_first.back());
    for (std::size_t r = 0; r < present.size(); ++r)
    {
      std::copy(lists[r].begin(), lists[r].end(), m_neighbors.begin() + m_first[present[r]]);
      std::vector<Index>().swap(lists[r]);
    }

    m_weight.assign(m_points.size(), 0);
    for_each_index<ConcurrencyTag>(
      present.size(),
      [&](std::size_t r) {
        const Index i = present[r];
        for (Index e = m_first[i]; e < m_first[i + 1]; ++e)
          m_weight[i] += weight(i, m_neighbors[e], stage);
      },
      [](std::size_t) { return true; });
  }

  template <typename Removed>
  bool eliminate(const Elimination_stage& stage, const Removed& removed)
  {
    std::vector<Indexed_heap::Entry> entries(m_points.size());
    for (Index i = 0; i < Index(m_points.size()); ++i)
      // absent points sink below every present one: they are never popped
      entries[i] = Indexed_heap::Entry{ is_present(i) ? -double(m_weight[i]) : 1., m_points.input_position[i], i };
    Indexed_heap heap(std::move(entries));

    while (m_count > stage.target)
    {
      const Index p = heap.top().id;
      heap.pop();
      m_present[p] = 0;
      --m_count;
      for (Index e = m_first[p]; e < m_first[p + 1]; ++e)
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
  double m_largest_scale = 1.;
  std::vector<char> m_present;
  std::size_t m_count;
  std::vector<Index> m_first;     // CSR offsets of each point's neighbours
  std::vector<Index> m_neighbors; // CSR neighbours
  std::vector<std::int64_t> m_weight;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_WEIGHTED_ELIMINATION_H
