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

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The swaps a run keeping `kept` points makes: one per thousand kept points,
// rounded up. The Hausdorff distance is set by a few points in the widest
// gaps; more swaps close narrower gaps, and take from the features the most
// crowded points are on.
inline std::size_t coverage_swap_count(std::size_t kept) { return (kept + 999) / 1000; }

// Each point's nearest present point (ties by input position), its cell,
// and the points not present farthest from theirs, kept up to date as
// points are made present or not. The present points of the start are
// searched in a tree, those made present since in a list: a few per
// thousand. The farthest points are a heap of every change, the outdated
// entries skipped when they come to the top.
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
  template <typename ConcurrencyTag>
  Nearest_present(const Indexed_points& points, Array<char>& present, const Array<Index>& sites, ConcurrencyTag)
    : m_points(points), m_present(present), m_tree(points, sites.begin(), sites.end(), ConcurrencyTag()),
      m_nearest(points.size()), m_first_member(points.size(), none), m_next_member(points.size(), none)
  {
    for_each_index<ConcurrencyTag>(
      points.size(),
      [&](std::size_t i) {
        m_nearest[i] = neighbor(Index(i), present[i] ? Index(i) : m_tree.nearest_one(Index(i)));
      },
      [](std::size_t) { return true; });
    for (Index i = 0; i < Index(points.size()); ++i)
    {
      link(i);
      if (!present[i])
        m_far.push_back(Neighbor{ m_nearest[i].squared_distance, points.input_position[i], i });
    }
    std::make_heap(m_far.begin(), m_far.end(), below);
  }

  // The point farthest from the present points, or nothing when every point is present.
  std::optional<Index> farthest()
  {
    while (!m_far.empty() && (m_present[m_far.front().id] ||
                              m_far.front().squared_distance != m_nearest[m_far.front().id].squared_distance))
    {
      std::pop_heap(m_far.begin(), m_far.end(), below);
      m_far.pop_back();
    }
    return m_far.empty() ? std::nullopt : std::optional<Index>(m_far.front().id);
  }

  bool is_present(Index i) const { return m_present[i] != 0; }

  // The greatest squared distance from a point to the present points.
  double greatest_squared_distance()
  {
    const std::optional<Index> f = farthest();
    return f ? m_nearest[*f].squared_distance : 0.;
  }

  // The present point nearest `q` other than `q` and `excluded`, at an
  // infinite distance when there is none.
  Neighbor nearest_but(Index q, Index excluded) const
  {
    thread_local Array<Neighbor> best;
    Neighbor result{ std::numeric_limits<double>::infinity(), none, none };
    m_tree.nearest(q, 2, best);
    for (const Neighbor& b : best)
      if (b.id != excluded)
      {
        result = b;
        break;
      }
    for (Index a : m_added)
      if (a != q && a != excluded)
        result = (std::min)(result, neighbor(q, a));
    return result;
  }

  // Makes `x` present: it takes into its cell the points nearer it than to
  // their present points. None is farther from its own than the farthest
  // point, so when `x` is that point they lie in the cells of the present
  // points within twice its distance.
  void make_present(Index x)
  {
    const double squared_reach = 4. * m_nearest[x].squared_distance * (1. + 1e-9);
    const Array<Index> near = present_within(x, squared_reach);
    m_present[x] = 1;
    m_added.push_back(x);
    move(x, neighbor(x, x));
    for (Index s : near)
      for (Index p : members(s))
        if (neighbor(p, x) < m_nearest[p])
          move(p, neighbor(p, x));
  }

  // The members of `y`'s cell with their nearest present points other than
  // `y`: where they go once `y` is no longer present.
  Array<std::pair<Index, Neighbor> > cell_without(Index y) const
  {
    Array<std::pair<Index, Neighbor> > moves;
    for (Index p : members(y))
      moves.emplace_back(p, nearest_but(p, y));
    return moves;
  }

  // Makes `y` no longer present, the members of its cell going as
  // `moves` (cell_without(y)) says.
  void make_absent(Index y, const Array<std::pair<Index, Neighbor> >& moves)
  {
    m_present[y] = 0;
    const auto added = std::find(m_added.begin(), m_added.end(), y);
    if (added != m_added.end())
      m_added.erase(added);
    else
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
    for (Index a : m_added)
      if (a != q && neighbor(q, a).squared_distance <= squared_reach)
        result.push_back(a);
    return result;
  }

  // `p` joins the cell of `site`, its new nearest present point.
  void move(Index p, const Neighbor& site)
  {
    Index* at = &m_first_member[m_nearest[p].id];
    while (*at != p)
      at = &m_next_member[*at];
    *at = m_next_member[p];
    m_nearest[p] = site;
    link(p);
    if (!m_present[p])
    {
      m_far.push_back(Neighbor{ site.squared_distance, m_points.input_position[p], p });
      std::push_heap(m_far.begin(), m_far.end(), below);
    }
  }

  void link(Index p)
  {
    m_next_member[p] = m_first_member[m_nearest[p].id];
    m_first_member[m_nearest[p].id] = p;
  }

  const Indexed_points& m_points;
  Array<char>& m_present;
  Point_tree m_tree;    // the present points of the start, less those made absent
  Array<Index> m_added; // the points made present since
  Array<Neighbor> m_nearest;
  Array<Index> m_first_member, m_next_member; // each cell's members, as a list
  Array<Neighbor> m_far; // the points not present, by their distance at each change
};

// The present points, most crowded first: by the distance to their nearest
// other present point (ties by input position).
template <typename ConcurrencyTag>
Array<Neighbor> present_by_crowding(const Indexed_points& points, const Array<Index>& sites)
{
  const Point_tree tree(points, sites.begin(), sites.end(), ConcurrencyTag());
  Array<Neighbor> crowding(sites.size());
  for_each_index<ConcurrencyTag>(
    sites.size(),
    [&](std::size_t r) {
      const Index s = sites[r];
      crowding[r] = Neighbor{ squared_distance(points.points[s], points.points[tree.nearest_one(s)]),
                              points.input_position[s], s };
    },
    [](std::size_t) { return true; });
  std::sort(crowding.begin(), crowding.end());
  return crowding;
}

// The present point that leaves once the farthest point is present: the
// next of `crowded`, from `next` on, still present and as crowded as it
// was, whose cell's members would all be nearer their new nearest present
// points than the farthest point then is. The points passed, and the one
// returned, are passed for good. Nothing when none is left.
inline std::optional<Index> next_to_leave(Nearest_present& nearest, const Array<Neighbor>& crowded,
                                          std::size_t& next)
{
  const double greatest = nearest.greatest_squared_distance();
  while (next < crowded.size())
  {
    const Neighbor& y = crowded[next++];
    if (!nearest.is_present(y.id) || nearest.nearest_but(y.id, y.id).squared_distance > y.squared_distance)
      continue;
    const Array<std::pair<Index, Neighbor> > moves = nearest.cell_without(y.id);
    if (std::all_of(moves.begin(), moves.end(),
                    [&](const std::pair<Index, Neighbor>& m) { return m.second.squared_distance < greatest; }))
    {
      nearest.make_absent(y.id, moves);
      return y.id;
    }
  }
  return std::nullopt;
}

// Up to `swaps` times, the point farthest from the present points becomes
// present and a crowded present point leaves (see next_to_leave), so that
// the swaps never raise the greatest distance from a point to the present
// points. They stop early when every point is present, or no present point
// can leave.
template <typename ConcurrencyTag>
void swap_farthest_for_crowded(const Indexed_points& points, Array<char>& present, std::size_t swaps)
{
  Array<Index> sites;
  for (Index i = 0; i < Index(points.size()); ++i)
    if (present[i])
      sites.push_back(i);
  if (sites.size() < 2 || sites.size() == points.size() || swaps == 0)
    return;
  const Array<Neighbor> crowded = present_by_crowding<ConcurrencyTag>(points, sites);
  Nearest_present nearest(points, present, sites, ConcurrencyTag());
  std::size_t next = 0;
  for (std::size_t swap = 0; swap < swaps; ++swap)
  {
    const std::optional<Index> x = nearest.farthest();
    if (!x)
      return;
    nearest.make_present(*x);
    if (!next_to_leave(nearest, crowded, next))
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
