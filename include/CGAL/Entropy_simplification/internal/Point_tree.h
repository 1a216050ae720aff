// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A CGAL Kd tree over point indices, with the package's exact neighbour order.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_POINT_TREE_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_POINT_TREE_H

#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// A neighbour in the making, ordered by (squared distance, input position):
// the neighbour order of every function of the package.
struct Neighbor
{
  double squared_distance;
  Index input_position;
  Index id;
  bool operator<(const Neighbor& other) const
  {
    return squared_distance < other.squared_distance ||
           (squared_distance == other.squared_distance && input_position < other.input_position);
  }
};

// A CGAL Kd tree over some of the indices of an Indexed_points. Searches are
// const and may run in parallel; `remove` may not.
class Point_tree
{
  using Point_map = CGAL::Pointer_property_map<Working_point>::const_type;
  using Traits = CGAL::Search_traits_adapter<Index, Point_map, CGAL::Search_traits_3<Working_kernel> >;
  using Tree = CGAL::Kd_tree<Traits>;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;

public:
  template <typename IndexIterator>
  Point_tree(const Indexed_points& points, IndexIterator first, IndexIterator beyond)
    : m_points(points), m_tree(first, beyond, Tree::Splitter(), Traits(CGAL::make_property_map(points.points)))
  {
    m_tree.build();
  }

  // Replaces `best` by the first `count` points of the tree other than `q`
  // in the neighbour order of `q` (all of them when fewer). A depth-first
  // search, closer child first, as CGAL::Orthogonal_k_neighbor_search, that
  // skips a subtree only when it is farther than the worst point kept, with a
  // margin for the rounding of the distance to its box: ties at that distance
  // are still considered, so the order is exact.
  void nearest(Index q, std::size_t count, std::vector<Neighbor>& best) const
  {
    best.clear();
    const Working_point& center = m_points.points[q];
    double offsets[3];
    const auto& box = m_tree.bounding_box();
    double distance = 0.;
    for (int d = 0; d < 3; ++d)
    {
      const double c = center.cartesian(d);
      offsets[d] = c < box.min_coord(d) ? box.min_coord(d) - c : (c > box.max_coord(d) ? c - box.max_coord(d) : 0.);
      distance += offsets[d] * offsets[d];
    }
    search(m_tree.root(), distance, offsets, q, count, best);
  }

  // Replaces `inside` by the points of the tree within `radius` of `center`,
  // possibly with a few at the boundary, in no particular order.
  void within(const Working_point& center, double radius, std::vector<Index>& inside) const
  {
    inside.clear();
    m_tree.search(std::back_inserter(inside),
                  Sphere(center, radius, 0., Traits(CGAL::make_property_map(m_points.points))));
  }

  void remove(Index p) { m_tree.remove(p, [p](Index i) { return i == p; }); }

private:
  void search(Tree::Node_const_handle node, double distance, double offsets[3], Index q, std::size_t count,
              std::vector<Neighbor>& best) const
  {
    const Working_point& center = m_points.points[q];
    if (node->is_leaf())
    {
      const auto leaf = static_cast<Tree::Leaf_node_const_handle>(node);
      for (auto it = leaf->begin(); it != leaf->end(); ++it)
        if (*it != q)
          keep_if_better(
            Neighbor{ squared_distance(center, m_points.points[*it]), m_points.input_position[*it], *it }, count,
            best);
      return;
    }
    const auto inner = static_cast<Tree::Internal_node_const_handle>(node);
    const int d = inner->cutting_dimension();
    const double c = center.cartesian(d);
    const double to_upper = c - inner->upper_low_value();
    const double to_lower = c - inner->lower_high_value();
    const bool lower_first = to_upper + to_lower < 0.;
    search(lower_first ? inner->lower() : inner->upper(), distance, offsets, q, count, best);

    const double offset = lower_first ? to_upper : to_lower;
    const double old_offset = offsets[d];
    const double other_distance = distance + offset * offset - old_offset * old_offset;
    if (best.size() < count || other_distance * (1. - 1e-12) <= best.back().squared_distance)
    {
      offsets[d] = offset;
      search(lower_first ? inner->upper() : inner->lower(), other_distance, offsets, q, count, best);
      offsets[d] = old_offset;
    }
  }

  static void keep_if_better(const Neighbor& candidate, std::size_t count, std::vector<Neighbor>& best)
  {
    if (best.size() == count)
    {
      if (!(candidate < best.back()))
        return;
      best.pop_back();
    }
    best.insert(std::upper_bound(best.begin(), best.end(), candidate), candidate);
  }

  const Indexed_points& m_points;
  Tree m_tree;
};

// The k nearest neighbours in `tree` of each point of `queries`, nearest
// first: those of `queries[r]` at `table[r * k]`. The tree must hold at least
// k points besides each query. Returns false when `progress` asked to stop.
template <typename ConcurrencyTag, typename Progress>
bool nearest_neighbor_table(const Point_tree& tree, const std::vector<Index>& queries, unsigned int k,
                            std::vector<Index>& table, const Progress& progress)
{
  table.resize(queries.size() * std::size_t(k));
  return for_each_index<ConcurrencyTag>(
    queries.size(),
    [&](std::size_t r) {
      thread_local std::vector<Neighbor> best;
      tree.nearest(queries[r], k, best);
      for (unsigned int j = 0; j < k; ++j)
        table[r * k + j] = best[j].id;
    },
    progress);
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_POINT_TREE_H
