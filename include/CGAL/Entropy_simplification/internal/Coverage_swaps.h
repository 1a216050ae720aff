// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The coverage swaps that end the default mode's relocation: the input point
// farthest from the present points is swapped in for a most crowded present
// point, a few times, so that the gaps the elimination left behind close.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_SWAPS_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_SWAPS_H

#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/Point_tree.h>
#include <CGAL/Entropy_simplification/internal/for_each_index.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The swaps a run keeping `kept` points makes: one per hundred kept points,
// rounded up. The widest gaps set the Hausdorff distance, the narrower ones
// weigh on the mean distance; each swap closes one, and takes a point from
// the most crowded (see crowding). Against one per thousand, on issue 12's
// cells (scratch): the Hausdorff distance 11 to 12% lower, the mean
// distance 0.3 to 0.6% lower, fandisk's edge share 0.6% and the ball's
// 1.2% lower. Three per hundred lowered the mean distance about twice as
// much, for shares 1.4 to 3.8% lower, and a ranking's prefixes, which get
// no swaps, fell behind the direct calls: on radar at 50%, 1.068 times
// their mean distance.
inline std::size_t coverage_swap_count(std::size_t kept) { return (kept + 99) / 100; }

// How crowded a present point is, the smaller the more: the squared
// distance to its nearest other present point over the square of its
// scale, the factor of its interaction radius. The elimination made the
// features dense on purpose; measured against the spacing it asked for, a
// point on a feature is no more crowded than one on a flat region (the
// edge share falls by 0.6% rather than 3.3% at ten swaps per thousand).
inline double crowding(double squared_distance, double scale) { return squared_distance / (scale * scale); }

// Each point's nearest present point (ties by input position), its cell,
// and the points not present farthest from theirs, kept up to date as
// points are made present or not. The searches run in a tree of every
// point, those not present left out. The farthest points are a heap of the
// points beyond a threshold and of every change since it was set, the
// outdated entries skipped when they come to the top; when none beyond the
// threshold is left, it is set again lower.
class Nearest_present
{
  static constexpr Index none = Index(-1);

  // the heap's order: farthest on top, then the lowest input position
  static bool below(const Neighbor& a, const Neighbor& b)
  {
    return a.squared_distance < b.squared_distance ||
           (a.squared_distance == b.squared_distance && a.input_position > b.input_position);
  }

public:
  // `sites`, the present points, in a tree of their own for the first search.
  template <typename ConcurrencyTag>
  Nearest_present(const Indexed_points& points, Array<char>& present, const Point_tree& sites, std::size_t heap_size,
                  ConcurrencyTag)
    : m_points(points), m_present(present),
      m_tree(points, boost::counting_iterator<Index>(0), boost::counting_iterator<Index>(Index(points.size())),
             ConcurrencyTag()),
      m_site(points.size()), m_first_member(points.size(), none), m_next_member(points.size(), none),
      m_heap_size(heap_size)
  {
    for_each_index<ConcurrencyTag>(
      points.size(), [&](std::size_t i) { m_site[i] = present[i] ? Index(i) : sites.nearest_one(Index(i)); },
      [](std::size_t) { return true; });
    for (Index i = 0; i < Index(points.size()); ++i)
    {
      link(i);
      if (!present[i])
        m_tree.remove(i);
    }
    fill_heap();
  }

  bool is_present(Index i) const { return m_present[i] != 0; }

  Neighbor nearest(Index i) const { return neighbor(i, m_site[i]); }

  // The point farthest from the present points, or nothing when every point is present.
  std::optional<Index> farthest()
  {
    for (;;)
    {
      while (!m_far.empty() && (m_present[m_far.front().id] ||
                                m_far.front().squared_distance != nearest(m_far.front().id).squared_distance))
      {
        std::pop_heap(m_far.begin(), m_far.end(), below);
        m_far.pop_back();
      }
      if (!m_far.empty() && m_far.front().squared_distance >= m_threshold)
        return m_far.front().id;
      if (m_threshold == 0.)
        return m_far.empty() ? std::nullopt : std::optional<Index>(m_far.front().id);
      fill_heap();
    }
  }

  // The greatest squared distance from a point to the present points.
  double greatest_squared_distance()
  {
    const std::optional<Index> f = farthest();
    return f ? nearest(*f).squared_distance : 0.;
  }

  // The present point nearest `q` other than `q` and `excluded`, at an
  // infinite distance when there is none.
  Neighbor nearest_but(Index q, Index excluded) const
  {
    thread_local Array<Neighbor> best;
    m_tree.nearest(q, 2, best);
    for (const Neighbor& b : best)
      if (b.id != excluded)
        return b;
    return Neighbor{ std::numeric_limits<double>::infinity(), none, none };
  }

  // Makes `x` present: it takes into its cell the points nearer it than to
  // their present points. None is farther from its own than the farthest
  // point, so when `x` is that point they lie in the cells of the present
  // points within twice its distance.
  void make_present(Index x)
  {
    const double squared_reach = 4. * nearest(x).squared_distance * (1. + 1e-9);
    const Array<Index> near = present_within(x, squared_reach);
    m_present[x] = 1;
    m_tree.restore(x);
    move(x, x);
    for (Index s : near)
      for (Index p : members(s))
        if (neighbor(p, x) < nearest(p))
          move(p, x);
  }

  // The members of `y`'s cell with their nearest present points other than
  // `y`: where they go once `y` is no longer present.
  Array<std::pair<Index, Index> > cell_without(Index y) const
  {
    Array<std::pair<Index, Index> > moves;
    for (Index p : members(y))
      moves.emplace_back(p, nearest_but(p, y).id);
    return moves;
  }

  // Makes `y` no longer present, the members of its cell going as
  // `moves` (cell_without(y)) says.
  void make_absent(Index y, const Array<std::pair<Index, Index> >& moves)
  {
    m_present[y] = 0;
    m_tree.remove(y);
    for (const auto& [p, site] : moves)
      move(p, site);
  }

private:
  Neighbor neighbor(Index q, Index site) const
  {
    return Neighbor{ squared_distance(m_points.points[q], m_points.points[site]), m_points.input_position[site],
                     site };
  }

  Array<Index> members(Index site) const
  {
    Array<Index> result;
    for (Index p = m_first_member[site]; p != none; p = m_next_member[p])
      result.push_back(p);
    return result;
  }

  // The present points within `squared_reach` of `q`, other than `q`.
  Array<Index> present_within(Index q, double squared_reach) const
  {
    Array<Neighbor> near;
    for (std::size_t count = 16;; count *= 4)
    {
      m_tree.nearest(q, count, near);
      if (near.size() < count || near.back().squared_distance > squared_reach)
        break;
    }
    Array<Index> result;
    for (const Neighbor& s : near)
      if (s.squared_distance <= squared_reach)
        result.push_back(s.id);
    return result;
  }

  // The heap holds again every point not present at least as far as the
  // `m_heap_size` farthest (all of them when as few), the threshold.
  void fill_heap()
  {
    Array<double> distances;
    for (Index i = 0; i < Index(m_points.size()); ++i)
      if (!m_present[i])
        distances.push_back(nearest(i).squared_distance);
    m_threshold = 0.;
    if (distances.size() > m_heap_size)
    {
      std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(m_heap_size - 1), distances.end(),
                       [](double a, double b) { return a > b; });
      m_threshold = distances[m_heap_size - 1];
    }
    Array<double>().swap(distances);
    m_far.clear();
    for (Index i = 0; i < Index(m_points.size()); ++i)
      if (!m_present[i] && nearest(i).squared_distance >= m_threshold)
        m_far.push_back(far_entry(i));
    std::make_heap(m_far.begin(), m_far.end(), below);
    m_heap_size *= 2;
  }

  // The heap's entry of `p`: its squared distance to its nearest present
  // point, its own input position, itself.
  Neighbor far_entry(Index p) const
  {
    return Neighbor{ nearest(p).squared_distance, m_points.input_position[p], p };
  }

  // `p` joins the cell of `site`, its new nearest present point.
  void move(Index p, Index site)
  {
    Index* at = &m_first_member[m_site[p]];
    while (*at != p)
      at = &m_next_member[*at];
    *at = m_next_member[p];
    m_site[p] = site;
    link(p);
    if (!m_present[p])
    {
      m_far.push_back(far_entry(p));
      std::push_heap(m_far.begin(), m_far.end(), below);
    }
  }

  void link(Index p)
  {
    m_next_member[p] = m_first_member[m_site[p]];
    m_first_member[m_site[p]] = p;
  }

  const Indexed_points& m_points;
  Array<char>& m_present;
  Point_tree m_tree;   // every point, those not present left out
  Array<Index> m_site; // each point's nearest present point
  Array<Index> m_first_member, m_next_member; // each cell's members, as a list
  std::size_t m_heap_size;
  double m_threshold = 0.;
  Array<Neighbor> m_far; // (squared distance, input position, point), as the heap's entries
};

// The present points, most crowded first (see crowding; ties by input
// position), their crowding in place of the squared distance.
template <typename ConcurrencyTag>
Array<Neighbor> present_by_crowding(const Indexed_points& points, const Array<Index>& sites, const Point_tree& tree,
                                    const Array<double>& scale)
{
  Array<Neighbor> crowded(sites.size());
  for_each_index<ConcurrencyTag>(
    sites.size(),
    [&](std::size_t r) {
      const Index s = sites[r];
      crowded[r] = Neighbor{ crowding(squared_distance(points.points[s], points.points[tree.nearest_one(s)]), scale[s]),
                             points.input_position[s], s };
    },
    [](std::size_t) { return true; });
  std::sort(crowded.begin(), crowded.end());
  return crowded;
}

// The present point that leaves once the farthest point is present: the
// next of `crowded`, from `next` on, still present and as crowded as it
// was, whose cell's members would all be nearer their new nearest present
// points than the farthest point then is. The points passed, and the one
// returned, are passed for good. Nothing when none is left.
inline std::optional<Index> next_to_leave(const Indexed_points& points, Nearest_present& nearest,
                                          const Array<Neighbor>& crowded, const Array<double>& scale,
                                          std::size_t& next)
{
  const double greatest = nearest.greatest_squared_distance();
  while (next < crowded.size())
  {
    const Neighbor& y = crowded[next++];
    if (!nearest.is_present(y.id) ||
        crowding(nearest.nearest_but(y.id, y.id).squared_distance, scale[y.id]) > y.squared_distance)
      continue;
    const Array<std::pair<Index, Index> > moves = nearest.cell_without(y.id);
    if (std::all_of(moves.begin(), moves.end(), [&](const std::pair<Index, Index>& m) {
          return squared_distance(points.points[m.first], points.points[m.second]) < greatest;
        }))
    {
      nearest.make_absent(y.id, moves);
      return y.id;
    }
  }
  return std::nullopt;
}

// Up to `swaps` times, the point farthest from the present points becomes
// present and a crowded present point leaves (see next_to_leave; `scale`,
// each point's, says how crowded), so that the swaps never raise the
// greatest distance from a point to the present points. They stop early when
// every point is present, or no present point can leave.
template <typename ConcurrencyTag>
void swap_farthest_for_crowded(const Indexed_points& points, Array<char>& present, std::size_t swaps,
                               const Array<double>& scale)
{
  Array<Index> sites;
  for (Index i = 0; i < Index(points.size()); ++i)
    if (present[i])
      sites.push_back(i);
  if (sites.size() < 2 || sites.size() == points.size() || swaps == 0)
    return;
  // the present points' own tree serves the first searches, and goes
  Array<Neighbor> crowded;
  Nearest_present nearest = [&] {
    const Point_tree tree(points, sites.begin(), sites.end(), ConcurrencyTag());
    crowded = present_by_crowding<ConcurrencyTag>(points, sites, tree, scale);
    return Nearest_present(points, present, tree, 64 * swaps, ConcurrencyTag());
  }();
  std::size_t next = 0;
  for (std::size_t swap = 0; swap < swaps; ++swap)
  {
    const std::optional<Index> x = nearest.farthest();
    if (!x)
      return;
    nearest.make_present(*x);
    if (!next_to_leave(points, nearest, crowded, scale, next))
    {
      nearest.make_absent(*x, nearest.cell_without(*x));
      return;
    }
  }
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_COVERAGE_SWAPS_H
