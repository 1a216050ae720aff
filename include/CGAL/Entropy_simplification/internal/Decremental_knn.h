// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact k nearest neighbours of every point of a set from which points are
// removed one at a time.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DECREMENTAL_KNN_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DECREMENTAL_KNN_H

#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/assertions.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The neighbour order of a point q: other present points sorted by squared
// distance to q, ties broken by input position. Its first k entries are the
// k nearest neighbours of q, which is what a from-scratch computation on the
// present points gives.
//
// Each point keeps a candidate list: an exact prefix of its neighbour order,
// of up to `capacity` points. Removing a point keeps every candidate list a
// prefix, so a list needs the Kd tree again only when fewer than k candidates
// are left. Reverse lists record, for each point s, the points q that have s
// among their k nearest neighbours: removing s changes exactly their
// neighbourhoods.
//
// Requires at least k + 1 present points at all times.
class Decremental_knn
{
  using Point_map = CGAL::Pointer_property_map<Working_point>::const_type;
  using Base_traits = CGAL::Search_traits_3<Working_kernel>;
  using Traits = CGAL::Search_traits_adapter<Index, Point_map, Base_traits>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Distance = Search::Distance;
  using Tree = Search::Tree;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;
  using Count = std::uint16_t;

  static constexpr Index none = (std::numeric_limits<Index>::max)();

  // A node of a reverse list; nodes live in one pool with a free list, so
  // removals allocate nothing once the pool has reached its working size.
  struct Reverse_node
  {
    Index point;
    Index next;
  };

public:
  static constexpr unsigned int largest_k = 1000;

  Decremental_knn(const Indexed_points& points, unsigned int k)
    : m_points(points),
      m_k(k),
      m_capacity(k + (std::max)(4u, k / 2)),
      m_point_map(CGAL::make_property_map(points.points)),
      m_tree(boost::counting_iterator<Index>(0), boost::counting_iterator<Index>(Index(points.size())),
             Tree::Splitter(), Traits(m_point_map)),
      m_candidates(points.size() * m_capacity),
      m_count(points.size(), 0),
      m_present(points.size(), 1),
      m_reverse_head(points.size(), none)
  {
    if (k == 0 || k > largest_k)
      throw std::invalid_argument("k must lie in [1, 1000]");
    if (points.size() < std::size_t(k) + 1)
      throw std::invalid_argument("k nearest neighbours need at least k + 1 points");
    m_tree.build();
  }

  std::size_t k() const { return m_k; }
  bool is_present(Index i) const { return m_present[i] != 0; }

  // The k nearest present neighbours of `i`, nearest first.
  const Index* neighbors(Index i) const { return &m_candidates[std::size_t(i) * m_capacity]; }

  // Fills every candidate list, then the reverse lists. `progress(done)` is
  // called between blocks of points, on the calling thread; returns false
  // when it asked to stop.
  template <typename ConcurrencyTag, typename Progress>
  bool initialize(const Progress& progress)
  {
    const bool completed = for_each_index<ConcurrencyTag>(
      m_points.size(), [&](std::size_t i) { fill_candidates(Index(i)); }, progress);
    if (!completed)
      return false;

    m_nodes.reserve(m_points.size() * m_k);
    for (Index q = 0; q < Index(m_points.size()); ++q)
      for (unsigned int j = 0; j < m_k; ++j)
        push_reverse(neighbors(q)[j], q);
    return true;
  }

  // Removes `p` and writes to `changed` the present points that had `p`
  // among their k nearest neighbours; each of them now has a new k-th one.
  void remove(Index p, std::vector<Index>& changed)
  {
    changed.clear();
    m_present[p] = 0;
    m_tree.remove(p, [p](Index i) { return i == p; });

    Index node = m_reverse_head[p];
    m_reverse_head[p] = none;
    while (node != none)
    {
      const Index q = m_nodes[node].point;
      const Index next = m_nodes[node].next;
      release_node(node);
      node = next;
      if (!is_present(q))
        continue;
      erase_candidate(q, p);
      if (m_count[q] < m_k)
        fill_candidates(q);
      push_reverse(neighbors(q)[m_k - 1], q);
      changed.push_back(q);
    }
  }

  // Calls `f(r)` for each present point r that has `q` among its k nearest
  // neighbours. Drops, on the way, the entries of points removed since.
  template <typename Function>
  void for_each_reverse_neighbor(Index q, const Function& f)
  {
    Index* link = &m_reverse_head[q];
    while (*link != none)
    {
      const Index node = *link;
      const Index r = m_nodes[node].point;
      if (is_present(r))
      {
        f(r);
        link = &m_nodes[node].next;
      }
      else
      {
        *link = m_nodes[node].next;
        release_node(node);
      }
    }
  }

private:
  bool precedes(const std::pair<double, Index>& a, const std::pair<double, Index>& b) const
  {
    if (a.first != b.first)
      return a.first < b.first;
    return m_points.input_position[a.second] < m_points.input_position[b.second];
  }

  // Sets the candidate list of `q` to the first `capacity` entries of its
  // neighbour order (or all of them when fewer points are present).
  void fill_candidates(Index q)
  {
    thread_local std::vector<std::pair<double, Index> > found;
    const Working_point& center = m_points.points[q];
    const std::size_t wanted = m_capacity + 1; // q itself comes back too

    found.clear();
    std::size_t returned = 0;
    Search search(m_tree, center, unsigned(wanted), 0., true, Distance(m_point_map));
    for (auto it = search.begin(); it != search.end(); ++it, ++returned)
      if (it->first != q)
        found.emplace_back(squared_distance(center, m_points.points[it->first]), it->first);
    std::size_t prefix = found.size();
    std::sort(found.begin(), found.end(),
              [this](const auto& a, const auto& b) { return precedes(a, b); });

    if (returned == wanted)
    {
      // Unreturned points lie at least as far as the farthest returned one;
      // entries tied with it (up to the tree's rounding) may be out of order.
      const double farthest = found.back().first;
      prefix = std::size_t(std::lower_bound(found.begin(), found.end(), farthest * (1. - 1e-12),
                                            [](const auto& e, double d) { return e.first < d; }) -
                           found.begin());
      if (prefix < m_k)
        prefix = collect_ties(q, farthest, found);
    }

    const std::size_t count = (std::min)(prefix, std::size_t(m_capacity));
    Index* list = &m_candidates[std::size_t(q) * m_capacity];
    for (std::size_t j = 0; j < count; ++j)
      list[j] = found[j].second;
    m_count[q] = Count(count);
  }

  // Heavy ties (e.g. duplicated points): replaces `found` by every present
  // point within `farthest` of `q`, in neighbour order, and returns its size.
  std::size_t collect_ties(Index q, double farthest, std::vector<std::pair<double, Index> >& found) const
  {
    thread_local std::vector<Index> inside;
    const Working_point& center = m_points.points[q];
    inside.clear();
    m_tree.search(std::back_inserter(inside),
                  Sphere(center, std::sqrt(farthest) * (1. + 1e-9), 0., Traits(m_point_map)));
    found.clear();
    for (Index i : inside)
    {
      const double d = squared_distance(center, m_points.points[i]);
      if (i != q && d <= farthest)
        found.emplace_back(d, i);
    }
    std::sort(found.begin(), found.end(),
              [this](const auto& a, const auto& b) { return precedes(a, b); });
    return found.size();
  }

  // Erases `p`, one of the k nearest neighbours of `q`, from the candidates of
  // `q`, with the spare candidates (beyond the k-th) removed since the list
  // was filled: the first k entries are then present again. The rest is
  // still a prefix of the neighbour order of `q` among the present points.
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

  void push_reverse(Index s, Index q)
  {
    Index node;
    if (m_free != none)
    {
      node = m_free;
      m_free = m_nodes[node].next;
    }
    else
    {
      node = Index(m_nodes.size());
      m_nodes.emplace_back();
    }
    m_nodes[node] = Reverse_node{ q, m_reverse_head[s] };
    m_reverse_head[s] = node;
  }

  void release_node(Index node)
  {
    m_nodes[node].next = m_free;
    m_free = node;
  }

  const Indexed_points& m_points;
  const unsigned int m_k;
  const unsigned int m_capacity;
  Point_map m_point_map;
  Tree m_tree;
  std::vector<Index> m_candidates; // m_capacity entries per point
  std::vector<Count> m_count;
  std::vector<char> m_present;
  std::vector<Index> m_reverse_head;
  std::vector<Reverse_node> m_nodes;
  Index m_free = none;
};

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_DECREMENTAL_KNN_H
