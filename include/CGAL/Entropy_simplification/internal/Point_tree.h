// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A tree of boxes over point indices, with the package's exact neighbour
// order.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_POINT_TREE_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_POINT_TREE_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

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

// The point `p` as a neighbour of the point `q`.
inline Neighbor neighbor_of(const Indexed_points& points, Index q, Index p)
{
  return Neighbor{ squared_distance(points.points[q], points.points[p]), points.input_position[p], p };
}

// A tree of boxes over some of the indices of an Indexed_points, down to
// leaves of at most `leaf_size` points. A node splits its indices where the
// kd order (see sort_spatially) splits the interval of indices it covers, so
// that on points in kd order each node holds the tree's points in one cell of
// a kd tree, with their bounding box, and the tree is built without moving a
// point. Its searches are exact on any points, only slower on others.
// Searches are const and may run in parallel; `remove` may not.
class Point_tree
{
  static constexpr std::size_t leaf_size = 20;
  // a leaf's points are scanned in chunks of at most this many (a leaf holds
  // more than leaf_size points only when indices repeat)
  static constexpr Index chunk_size = 32;
  // subtrees of more points are built in parallel under Parallel_tag
  static constexpr std::size_t parallel_build_size = std::size_t(1) << 16;

  // A node holds m_order[first, beyond); an inner node's children are
  // m_nodes[child] and m_nodes[child + 1], the second holding the indices
  // from `split` on; a leaf has child 0.
  struct Node
  {
    double low[3], high[3];
    Index first, beyond, child, split;
  };

public:
  template <typename IndexIterator, typename ConcurrencyTag = CGAL::Sequential_tag>
  Point_tree(const Indexed_points& points, IndexIterator first, IndexIterator beyond,
             ConcurrencyTag = ConcurrencyTag())
    : m_points(points), m_order(first, beyond)
  {
    if (!std::is_sorted(m_order.begin(), m_order.end()))
      std::sort(m_order.begin(), m_order.end());
    // laid out first, the nodes are then filled independently of each other
    m_nodes.reserve(2 * (m_order.size() / leaf_size + 1));
    m_nodes.push_back(Node());
    lay_out(0, 0, Index(m_order.size()), 0, points.size());
    fill<ConcurrencyTag>(0);
  }

  // Writes to `best`, which has room for them, the first `count` points of
  // the tree other than `q` in the neighbour order of `q` (all of them when
  // fewer); returns how many. A subtree is skipped only when its box is
  // farther than the worst point kept: the rounded distance to a box never
  // exceeds the rounded distance to a point inside it, so ties at that
  // distance are still considered and the order is exact.
  std::size_t nearest(Index q, std::size_t count, Neighbor* best) const
  {
    Best_list list{ count, best };
    if (!m_order.empty() && count > 0)
      search_nearest(q, list);
    return list.size;
  }

  // The same, replacing `best` by those points.
  void nearest(Index q, std::size_t count, Array<Neighbor>& best) const
  {
    best.resize(count);
    best.resize(nearest(q, count, best.data()));
  }

  // The same, or false, with `best` in no particular state, when a point of
  // the tree that does not coincide with `q` lies too near it to be told
  // apart (see too_near_to_tell_apart): the search then stops there, where
  // a search among many such points would visit every one of them.
  bool nearest_apart(Index q, std::size_t count, Array<Neighbor>& best) const
  {
    best.resize(count);
    Best_list_apart list{ { count, best.data() }, m_points.points[q], m_points.points };
    if (!m_order.empty() && count > 0)
      search_nearest(q, list);
    best.resize(list.size);
    return !list.too_near;
  }

  // The same, among the points that come before the point `than` only. The
  // search starts bounded by `than`, as in nearest_before(q, than).
  std::size_t nearest_before(Index q, std::size_t count, const Neighbor& than, Neighbor* best) const
  {
    Best_list_before list{ { count, best }, than };
    if (!m_order.empty() && count > 0)
      search_nearest(q, list);
    return list.size;
  }

  // The first point of the tree other than `q` in the neighbour order of
  // `q`, as `nearest(q, 1, ...)` finds it, with no list to keep. The tree
  // must hold a point other than `q`.
  Index nearest_one(Index q) const
  {
    Best_one one;
    search_nearest(q, one);
    return one.best.id;
  }

  // The first point of the tree other than `q` in the neighbour order of
  // `q`, as nearest_one() finds it, when it comes before the point `than`,
  // or `than` otherwise. The search starts bounded by `than`, so that it
  // visits only the leaves near `q`.
  Index nearest_before(Index q, Index than) const { return first_before(q, neighbor_of(m_points, q, than)).id; }

  // Records the largest of `scales` in each node, for `within_reach_of_leaf`.
  // Children follow their parent in m_nodes: a backward pass sees them first.
  void record_largest_scales(const Array<double>& scales)
  {
    m_largest_scale.assign(m_nodes.size(), 0.);
    for (std::size_t n = m_nodes.size(); n-- > 0;)
    {
      const Node& node = m_nodes[n];
      if (node.child != 0)
        m_largest_scale[n] = (std::max)(m_largest_scale[node.child], m_largest_scale[node.child + 1]);
      else
        for (Index r = node.first; r < node.beyond; ++r)
          m_largest_scale[n] = (std::max)(m_largest_scale[n], scales[m_order[r]]);
    }
  }

  // The leaves, in index order.
  Array<Index> leaves() const
  {
    Array<Index> result;
    if (!m_order.empty())
      append_leaves(0, result);
    return result;
  }

  // Calls `f(i, inside)` for each point i of the leaf `leaf` (one of
  // leaves()), in index order, with `inside` the points j of the tree within
  // `radius` times (`scales[i]` + `scales[j]`) of i, possibly with a few more
  // at that distance, in no particular order. The leaves that can hold such
  // points are found once for all the points of the leaf, a node being
  // skipped at the reach of the two boxes' largest scales. `scales` must be
  // those recorded.
  template <typename Function>
  void within_reach_of_leaf(Index leaf, double radius, const Array<double>& scales, const Function& f) const
  {
    thread_local Array<Index> near, inside;
    near.clear();
    search_leaves_within_reach(0, m_nodes[leaf], radius, m_largest_scale[leaf], near);
    for (Index r = m_nodes[leaf].first; r < m_nodes[leaf].beyond; ++r)
    {
      const Index i = m_order[r];
      inside.clear();
      for (Index n : near)
        append_within_reach(n, m_points.points[i], radius, scales[i], scales, inside);
      f(i, static_cast<const Array<Index>&>(inside));
    }
  }

  // Leaves `p` out of later searches; the boxes stay as they were.
  void remove(Index p)
  {
    if (m_removed.empty())
      m_removed.assign(m_points.size(), 0);
    m_removed[p] = 1;
  }

  // Brings a removed `p` back into later searches.
  void restore(Index p) { m_removed[p] = 0; }

private:
  // Node `node` holds m_order[first, beyond), the tree's indices in
  // [low, high), which splits where the kd order splits it, in halves; when
  // all of them fall in one half, that half is split in turn.
  void lay_out(std::size_t node, Index first, Index beyond, std::size_t low, std::size_t high)
  {
    m_nodes[node].first = first;
    m_nodes[node].beyond = beyond;
    m_nodes[node].child = 0;
    if (beyond - first <= leaf_size)
      return;
    for (;;)
    {
      // repeated indices end the splitting rather than split forever
      if (high - low < 2)
        return;
      const std::size_t half = low + (high - low) / 2;
      const Index middle =
        Index(std::lower_bound(m_order.begin() + first, m_order.begin() + beyond, half) - m_order.begin());
      if (middle == first)
        low = half;
      else if (middle == beyond)
        high = half;
      else
      {
        const Index child = Index(m_nodes.size());
        m_nodes[node].child = child;
        m_nodes[node].split = Index(half);
        m_nodes.resize(m_nodes.size() + 2);
        lay_out(child, first, middle, low, half);
        lay_out(child + 1, middle, beyond, half, high);
        return;
      }
    }
  }

  // The box of a node: of its points for a leaf, of its children's boxes
  // otherwise.
  template <typename ConcurrencyTag>
  void fill(std::size_t n)
  {
    Node& node = m_nodes[n];
    for (int d = 0; d < 3; ++d)
    {
      node.low[d] = HUGE_VAL;
      node.high[d] = -HUGE_VAL;
    }
    if (node.child == 0)
    {
      for (Index r = node.first; r < node.beyond; ++r)
        for (int d = 0; d < 3; ++d)
        {
          const double c = m_points.points[m_order[r]].cartesian(d);
          node.low[d] = (std::min)(node.low[d], c);
          node.high[d] = (std::max)(node.high[d], c);
        }
      return;
    }
    const Index child = node.child;
#ifdef CGAL_LINKED_WITH_TBB
    if (std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value &&
        node.beyond - node.first > parallel_build_size)
      tbb::parallel_invoke([&] { fill<ConcurrencyTag>(child); }, [&] { fill<ConcurrencyTag>(child + 1); });
    else
#endif
    {
      fill<ConcurrencyTag>(child);
      fill<ConcurrencyTag>(child + 1);
    }
    for (const Node& part : { m_nodes[child], m_nodes[child + 1] })
      for (int d = 0; d < 3; ++d)
      {
        node.low[d] = (std::min)(node.low[d], part.low[d]);
        node.high[d] = (std::max)(node.high[d], part.high[d]);
      }
  }

  bool is_removed(Index i) const { return !m_removed.empty() && m_removed[i]; }

  // The first point of the tree other than `q` in the neighbour order of
  // `q`, if it comes before `than`, or `than`.
  Neighbor first_before(Index q, const Neighbor& than) const
  {
    Best_one one;
    one.best = than;
    if (!m_order.empty())
      search_nearest(q, one);
    return one.best;
  }

  static double squared_distance_to_box(const Working_point& q, const Node& node)
  {
    double distance = 0.;
    for (int d = 0; d < 3; ++d)
    {
      const double c = q.cartesian(d);
      const double offset = c < node.low[d] ? node.low[d] - c : (c > node.high[d] ? c - node.high[d] : 0.);
      distance += offset * offset;
    }
    return distance;
  }

public:
  // The best points found so far: a list of at most `count` in the
  // neighbour order, or a single one. A point farther than `bound()` cannot
  // enter.
  struct Best_list
  {
    std::size_t count;
    Neighbor* list; // room for `count`
    std::size_t size = 0;
    double bound() const
    {
      return size < count ? std::numeric_limits<double>::infinity() : list[size - 1].squared_distance;
    }
    // The candidate moves up from the end of the list: the lists are short,
    // and a linear walk costs less than a binary search's mispredicted
    // branches.
    void offer(const Neighbor& candidate)
    {
      std::size_t slot = size;
      if (slot == count)
      {
        if (!(candidate < list[slot - 1]))
          return;
        --slot;
      }
      else
        ++size;
      for (; slot > 0 && candidate < list[slot - 1]; --slot)
        list[slot] = list[slot - 1];
      list[slot] = candidate;
    }
  };

  // A Best_list that only the points before `than` enter.
  struct Best_list_before : Best_list
  {
    Neighbor than;
    double bound() const { return size < count ? than.squared_distance : Best_list::bound(); }
    void offer(const Neighbor& candidate)
    {
      if (candidate < than)
        Best_list::offer(candidate);
    }
  };

  // A Best_list that stops, bounded below every distance, at the first
  // point too near the point `q` to be told apart from it.
  struct Best_list_apart : Best_list
  {
    const Working_point& q;
    const Array<Working_point>& points;
    bool too_near = false;
    double bound() const { return too_near ? -1. : Best_list::bound(); }
    void offer(const Neighbor& candidate)
    {
      too_near = too_near || too_near_to_tell_apart(q, points[candidate.id], candidate.squared_distance);
      if (!too_near)
        Best_list::offer(candidate);
    }
  };

private:
  struct Best_one
  {
    Neighbor best{ std::numeric_limits<double>::infinity(), 0, 0 };
    double bound() const { return best.squared_distance; }
    void offer(const Neighbor& candidate)
    {
      if (candidate < best)
        best = candidate;
    }
  };

  // From the leaf whose interval of indices holds `q` (or the nearest by
  // index), near `q` on points in kd order, up to the root, searching on the
  // way the other child of each node of the path unless its box is farther
  // than the bound. Every node off the path lies under one of those other
  // children, so the search is exact whichever leaf the path reaches; found
  // by index, the path needs none of its boxes measured, and on points in
  // kd order they hold `q` or nearly.
  template <typename Best>
  void search_nearest(Index q, Best& best) const
  {
    // each split halves an interval of indices, so no path is longer than
    // 32 nodes
    Index path[64];
    std::size_t depth = 0;
    Index n = 0;
    for (; m_nodes[n].child != 0; n = m_nodes[n].child + Index(q >= m_nodes[n].split))
      path[depth++] = n;
    search_subtree(n, q, best);
    const Working_point& center = m_points.points[q];
    while (depth > 0)
    {
      const Node& node = m_nodes[path[--depth]];
      const Index other = node.child + Index(q < node.split);
      if (squared_distance_to_box(center, m_nodes[other]) <= best.bound())
        search_subtree(other, q, best);
    }
  }

  // The search of the subtree of node `n`, depth first, the child whose box
  // is nearer `q` first; the farther one waits, and is skipped if its box is
  // then farther than the bound. The search is a loop rather than a
  // recursion, which costs a call per level.
  template <typename Best>
  void search_subtree(Index n, Index q, Best& best) const
  {
    // at most one child per node of a path waits
    struct Waiting
    {
      Index node;
      double squared_distance;
    };
    Waiting waiting[64];
    std::size_t waiting_count = 0;
    const Working_point& center = m_points.points[q];
    for (;;)
    {
      const Node& node = m_nodes[n];
      if (node.child == 0)
        // (an Index would wrap past the last chunk of indices near 2^32)
        for (std::size_t first = node.first; first < node.beyond; first += chunk_size)
        {
          // most points of a leaf lie beyond the bound: they are sorted out
          // without a branch, and only the others are offered
          double distance[chunk_size];
          Index near[chunk_size];
          const Index count = Index((std::min)(std::size_t(chunk_size), node.beyond - first));
          const double bound = best.bound();
          Index near_count = 0;
          for (Index j = 0; j < count; ++j)
          {
            distance[j] = squared_distance(center, m_points.points[m_order[first + j]]);
            near[near_count] = j;
            near_count += Index(distance[j] <= bound);
          }
          for (Index t = 0; t < near_count; ++t)
          {
            const Index j = near[t], i = m_order[first + j];
            if (distance[j] <= best.bound() && i != q && !is_removed(i))
              best.offer(Neighbor{ distance[j], m_points.input_position[i], i });
          }
        }
      else
      {
        Index nearer = node.child, farther = node.child + 1;
        double nearer_distance = squared_distance_to_box(center, m_nodes[nearer]);
        double farther_distance = squared_distance_to_box(center, m_nodes[farther]);
        if (farther_distance < nearer_distance)
        {
          std::swap(nearer, farther);
          std::swap(nearer_distance, farther_distance);
        }
        if (farther_distance <= best.bound())
          waiting[waiting_count++] = Waiting{ farther, farther_distance };
        if (nearer_distance <= best.bound())
        {
          n = nearer;
          continue;
        }
      }
      do
      {
        if (waiting_count == 0)
          return;
        --waiting_count;
      } while (waiting[waiting_count].squared_distance > best.bound());
      n = waiting[waiting_count].node;
    }
  }

  // The reach is widened by 1e-9 so that rounding never loses a point at it.
  static double widened(double reach) { return reach * (1. + 1e-9); }

  void append_leaves(Index n, Array<Index>& leaves) const
  {
    if (m_nodes[n].child == 0)
      leaves.push_back(n);
    else
    {
      append_leaves(m_nodes[n].child, leaves);
      append_leaves(m_nodes[n].child + 1, leaves);
    }
  }

  static double squared_distance_between_boxes(const Node& a, const Node& b)
  {
    double distance = 0.;
    for (int d = 0; d < 3; ++d)
    {
      const double offset = a.high[d] < b.low[d] ? b.low[d] - a.high[d] : (b.high[d] < a.low[d] ? a.low[d] - b.high[d] : 0.);
      distance += offset * offset;
    }
    return distance;
  }

  // Appends to `near` the leaves under node `n` that can hold a point within
  // reach of a point of the box `box`, whose points' largest scale is `scale`.
  void search_leaves_within_reach(Index n, const Node& box, double radius, double scale, Array<Index>& near) const
  {
    const Node& node = m_nodes[n];
    const double reach = widened(radius * (scale + m_largest_scale[n]));
    if (squared_distance_between_boxes(box, node) > reach * reach)
      return;
    if (node.child == 0)
    {
      near.push_back(n);
      return;
    }
    search_leaves_within_reach(node.child, box, radius, scale, near);
    search_leaves_within_reach(node.child + 1, box, radius, scale, near);
  }

  // Appends to `inside` the points of leaf `n` within reach of `center`.
  void append_within_reach(Index n, const Working_point& center, double radius, double scale,
                           const Array<double>& scales, Array<Index>& inside) const
  {
    const Node& node = m_nodes[n];
    const double node_reach = widened(radius * (scale + m_largest_scale[n]));
    if (squared_distance_to_box(center, node) > node_reach * node_reach)
      return;
    // as in search_subtree, the points within reach are sorted out without a
    // branch
    for (std::size_t first = node.first; first < node.beyond; first += chunk_size)
    {
      Index near[chunk_size];
      const Index count = Index((std::min)(std::size_t(chunk_size), node.beyond - first));
      Index near_count = 0;
      for (Index j = 0; j < count; ++j)
      {
        const Index i = m_order[first + j];
        const double reach = widened(radius * (scale + scales[i]));
        near[near_count] = i;
        near_count += Index(squared_distance(center, m_points.points[i]) <= reach * reach);
      }
      for (Index t = 0; t < near_count; ++t)
        if (!is_removed(near[t]))
          inside.push_back(near[t]);
    }
  }

  const Indexed_points& m_points;
  Array<Index> m_order; // the tree's points in index order, each node's contiguous
  Growing_array<Node> m_nodes; // often more than the room reserved for them
  Array<char> m_removed; // empty until a removal
  Array<double> m_largest_scale; // of each node, for within_reach_of_leaf
};

// The k nearest neighbours in `tree` of each point of `queries`, nearest
// first: those of `queries[r]` at `table[r * k]`. The tree must hold at least
// k points besides each query. Returns false when `progress` asked to stop;
// throws std::invalid_argument when two of the points are too near to be
// told apart (see too_near_to_tell_apart). The table, large with a large k,
// grows 4M entries at a time.
template <typename ConcurrencyTag, typename Progress>
bool nearest_neighbor_table(const Point_tree& tree, const Array<Index>& queries, unsigned int k,
                            Array<Index>& table, const Progress& progress)
{
  table.clear();
  reserve_untouched(table, queries.size() * std::size_t(k));
  std::atomic<bool> too_near(false);
  const bool completed = for_each_index_growing<ConcurrencyTag>(
    queries.size(), (std::max)(std::size_t(1), (std::size_t(1) << 22) / k),
    [&](std::size_t rows) { grow_touched(table, rows * k); },
    [&](std::size_t r) {
      thread_local Array<Neighbor> best;
      if (!tree.nearest_apart(queries[r], k, best))
      {
        too_near.store(true, std::memory_order_relaxed);
        return;
      }
      for (unsigned int j = 0; j < k; ++j)
        table[r * k + j] = best[j].id;
    },
    [&](std::size_t done) { return !too_near.load(std::memory_order_relaxed) && progress(done); });
  if (too_near)
    throw points_too_near_to_tell_apart();
  return completed;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_POINT_TREE_H
