// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default mode (weighted elimination, then relocation) computed from
// scratch: every weight is the sum over all present pairs before every
// removal, every nearest point a scan of all points. It shares with the
// package the feature field of a neighbourhood, the stage formula and the
// weight of one pair, not the data structures under test (Kd tree, neighbour
// lists, incremental weights, heap, spatial order, cells).

#ifndef ENTROPY_SIMPLIFICATION_TEST_BRUTE_FORCE_ELIMINATION_H
#define ENTROPY_SIMPLIFICATION_TEST_BRUTE_FORCE_ELIMINATION_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Weighted_elimination.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace brute_force {

namespace ESI = CGAL::Entropy_simplification::internal;

struct Elimination_result
{
  std::vector<std::size_t> removed; // input positions, first removed first
  ESI::Elimination_field field;     // by input position
};

inline Elimination_result elimination_sequence(const std::vector<ESI::Working_point>& points, unsigned int k,
                                               std::size_t target,
                                               const CGAL::Entropy_simplification::Options& options)
{
  const std::size_t n = points.size();
  // the points in input order, each its own input position
  ESI::Indexed_points identity;
  identity.points = points;
  for (std::size_t i = 0; i < n; ++i)
    identity.input_position.push_back(ESI::Index(i));

  std::vector<ESI::Index> knn;
  for (std::size_t i = 0; i < n; ++i)
  {
    std::vector<std::pair<double, std::size_t> > order;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i)
        order.emplace_back(ESI::squared_distance(points[i], points[j]), j);
    std::sort(order.begin(), order.end());
    for (unsigned int j = 0; j < k; ++j)
      knn.push_back(ESI::Index(order[j].second));
  }

  // the coarse scale: the same points as the package's, every stride-th of the spatial order
  const ESI::Indexed_points sorted = ESI::sort_spatially(points);
  std::vector<ESI::Index> coarse;
  for (std::size_t j = 0; j < n; j += ESI::coarse_stride)
    coarse.push_back(sorted.input_position[j]);

  Elimination_result result;
  ESI::compute_elimination_field<CGAL::Sequential_tag>(
    identity, coarse, k, options, [&](ESI::Index i) { return &knn[std::size_t(i) * k]; }, result.field,
    [](double) { return true; });

  std::vector<bool> present(n, true);
  std::size_t count = n;
  while (count > target)
  {
    const ESI::Elimination_stage stage = ESI::next_stage(count, target, result.field.effective_area);
    while (count > stage.target)
    {
      std::size_t best = n;
      std::int64_t best_weight = 0;
      for (std::size_t i = 0; i < n; ++i)
      {
        if (!present[i])
          continue;
        std::int64_t w = 0;
        for (std::size_t j = 0; j < n; ++j)
          if (present[j] && j != i)
            w += ESI::pair_weight(points[i], points[j], result.field.scale[i], result.field.scale[j], stage);
        // strictly greater keeps the lowest input position among ties
        if (best == n || w > best_weight)
        {
          best = i;
          best_weight = w;
        }
      }
      present[best] = false;
      --count;
      result.removed.push_back(best);
    }
  }
  return result;
}

// Lloyd's relaxation restricted to the input points, by its definition: each
// point joins the cell of its nearest present point (ties: lowest input
// position), each cell keeps the member nearest its centroid (same ties).
inline std::vector<bool> relocate(const std::vector<ESI::Working_point>& points, std::vector<bool> present,
                                  int iterations)
{
  const std::size_t n = points.size();
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    std::vector<std::size_t> cell(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      cell[i] = n;
      for (std::size_t j = 0; j < n && !present[i]; ++j)
        if (present[j] && (cell[i] == n || ESI::squared_distance(points[i], points[j]) <
                                             ESI::squared_distance(points[i], points[cell[i]])))
          cell[i] = j;
      if (present[i])
        cell[i] = i;
    }
    std::vector<std::array<double, 4> > sum(n, { 0., 0., 0., 0. });
    for (std::size_t i = 0; i < n; ++i)
    {
      sum[cell[i]][0] += points[i].x();
      sum[cell[i]][1] += points[i].y();
      sum[cell[i]][2] += points[i].z();
      sum[cell[i]][3] += 1.;
    }
    std::vector<bool> relocated(n, false);
    for (std::size_t c = 0; c < n; ++c)
    {
      if (!present[c])
        continue;
      const ESI::Working_point centroid(sum[c][0] / sum[c][3], sum[c][1] / sum[c][3], sum[c][2] / sum[c][3]);
      std::size_t best = n;
      for (std::size_t i = 0; i < n; ++i)
        if (cell[i] == c &&
            (best == n || ESI::squared_distance(points[i], centroid) < ESI::squared_distance(points[best], centroid)))
          best = i;
      relocated[best] = true;
    }
    present = relocated;
  }
  return present;
}

// The removal order of the default mode: the elimination's, where each point
// the relocation drops takes the place of the point that replaces it, both
// taken in input order.
inline std::vector<std::size_t> default_mode_sequence(const std::vector<ESI::Working_point>& points,
                                                      unsigned int k, std::size_t target,
                                                      const CGAL::Entropy_simplification::Options& options,
                                                      int relocation_iterations)
{
  std::vector<std::size_t> removed = elimination_sequence(points, k, target, options).removed;
  std::vector<bool> eliminated(points.size(), true);
  for (std::size_t i : removed)
    eliminated[i] = false;
  const std::vector<bool> relocated = relocate(points, eliminated, relocation_iterations);
  std::vector<std::size_t> gone, come;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (eliminated[i] && !relocated[i])
      gone.push_back(i);
    if (!eliminated[i] && relocated[i])
      come.push_back(i);
  }
  for (std::size_t j = 0; j < gone.size(); ++j)
    *std::find(removed.begin(), removed.end(), come[j]) = gone[j];
  return removed;
}

} // namespace brute_force

#endif // ENTROPY_SIMPLIFICATION_TEST_BRUTE_FORCE_ELIMINATION_H
