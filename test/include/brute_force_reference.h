// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's method computed from scratch after every removal: slow and
// obviously correct. It shares with the package only the numeric routines of
// one neighbourhood (distance, normal, angle, entropy, reference plane), not
// the data structures under test (Kd tree, candidate and reverse lists, heap,
// spatial order).

#ifndef ENTROPY_SIMPLIFICATION_TEST_BRUTE_FORCE_REFERENCE_H
#define ENTROPY_SIMPLIFICATION_TEST_BRUTE_FORCE_REFERENCE_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>
#include <CGAL/Entropy_simplification/internal/normal_angle_entropy.h>
#include <CGAL/Entropy_simplification/internal/reference_plane.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace brute_force {

namespace ES = CGAL::Entropy_simplification;
using ES::internal::Working_point;
using ES::internal::Working_vector;

struct State
{
  std::vector<std::vector<std::size_t> > neighbors; // per input position, empty when removed
  std::vector<Working_vector> normals;
  std::vector<double> importance;
};

// Neighbourhoods, normals and importances of the present points, from scratch.
inline State compute_state(const std::vector<Working_point>& points, const std::vector<bool>& present,
                           unsigned int k, const ES::Options& options, const Working_vector& reference)
{
  const std::size_t n = points.size();
  State s;
  s.neighbors.resize(n);
  s.normals.resize(n);
  s.importance.resize(n);
  std::vector<ES::internal::Angle_term> angles(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!present[i])
      continue;
    std::vector<std::pair<double, std::size_t> > order;
    for (std::size_t j = 0; j < n; ++j)
      if (present[j] && j != i)
        order.emplace_back(ES::internal::squared_distance(points[i], points[j]), j);
    std::sort(order.begin(), order.end()); // by distance, then input position
    for (unsigned int j = 0; j < k; ++j)
      s.neighbors[i].push_back(order[j].second);
    s.normals[i] = ES::internal::estimate_normal(
      options.normal_estimation, k + 1,
      [&](std::size_t j) -> const Working_point& { return points[j == 0 ? i : s.neighbors[i][j - 1]]; });
    angles[i] = ES::internal::make_angle_term(ES::internal::normal_angle(s.normals[i], reference));
  }
  for (std::size_t i = 0; i < n; ++i)
    if (present[i])
      s.importance[i] = ES::internal::angle_entropy(k + 1, [&](std::size_t j) -> const ES::internal::Angle_term& {
        return angles[j == 0 ? i : s.neighbors[i][j - 1]];
      });
  return s;
}

// The input positions of the removed points, in removal order, and the final state.
inline std::pair<std::vector<std::size_t>, State>
removal_sequence(const std::vector<Working_point>& points, unsigned int k, std::size_t target,
                 const ES::Options& options)
{
  // A copy of an earlier point (equal as doubles) goes first, the last first;
  // the method runs on the other points.
  std::vector<bool> present(points.size(), true);
  std::vector<std::size_t> removed;
  for (std::size_t i = points.size(); i-- > 0 && points.size() - removed.size() > target;)
    for (std::size_t j = 0; j < i && present[i]; ++j)
      if (points[j] == points[i])
      {
        present[i] = false;
        removed.push_back(i);
      }
  std::vector<Working_point> distinct;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (present[i])
      distinct.push_back(points[i]);
  const Working_vector reference = ES::internal::reference_normal(options, distinct);
  State state = compute_state(points, present, k, options, reference);
  while (points.size() - removed.size() > target)
  {
    const bool lowest = options.removal_order == ES::Removal_order::lowest_entropy_first;
    std::size_t best = points.size();
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      if (!present[i])
        continue;
      // strict comparisons keep the lowest input position among ties
      if (best == points.size() ||
          (lowest ? state.importance[i] < state.importance[best] : state.importance[i] > state.importance[best]))
        best = i;
    }
    present[best] = false;
    removed.push_back(best);
    state = compute_state(points, present, k, options, reference);
  }
  return { removed, state };
}

} // namespace brute_force

#endif // ENTROPY_SIMPLIFICATION_TEST_BRUTE_FORCE_REFERENCE_H
